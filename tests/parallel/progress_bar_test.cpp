// The progress line of long runs: what is done, the time taken and the time left at the rate so
// far (an overnight sweep said only its count).
#include "parallel/progress_bar.hpp"

#include <gtest/gtest.h>

namespace gaitopt::parallel {
namespace {

TEST(ProgressText, SaysTheCountTheTimeTakenAndTheTimeLeftAtTheRateSoFar) {
  EXPECT_EQ(progressText("stability", 25, 100, 90),
            "stability [#######.......................]  25% 25/100, 1m30s elapsed, about 4m30s "
            "left");
  // nothing done yet: no rate to carry to the end
  EXPECT_EQ(progressText("map", 0, 7, 3.4),
            "map [..............................]   0% 0/7, 3s elapsed");
  // done: no time left to say; hours past the first
  EXPECT_EQ(progressText("map", 7, 7, 7400),
            "map [##############################] 100% 7/7, 2h03m elapsed");
}

}  // namespace
}  // namespace gaitopt::parallel
