// The walk's record of its steps (sim/walk/hybrid_walk.hpp): a touchdown far short of the planned
// step is a scuff at mid-swing that ends the walk, not a step walked; steps a push or a model
// error shortens still count.
#include <gtest/gtest.h>

#include "sim/walk/hybrid_walk.hpp"

namespace gaitopt::sim {
namespace {

StepResult stepOf(double advance) {
  StepResult s;
  s.ok = true;
  s.advance = advance;
  s.slip = 1e-4;
  return s;
}

TEST(AppendStep, AScuffAtMidSwingIsNotAStep) {
  WalkResult w;
  EXPECT_TRUE(appendStep(w, stepOf(0.3), 0.5));    // 60 %: a shortened step
  EXPECT_FALSE(appendStep(w, stepOf(3e-5), 0.5));  // the legs together
  EXPECT_EQ(w.steps_completed, 1);
  EXPECT_TRUE(w.fell);
  EXPECT_NE(w.failure.find("step 2: the swing tip struck the ground 3e-05 m ahead of the stance "
                           "tip, 0 % of the planned 0.5 m step"),
            std::string::npos)
      << w.failure;
  EXPECT_EQ(w.max_slip, 1e-4);  // the failed step's record is kept
}

}  // namespace
}  // namespace gaitopt::sim
