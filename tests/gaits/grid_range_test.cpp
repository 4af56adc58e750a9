// Ranges "a:b:n" and "a" as the command line writes them (gaits/impact/grid_range.hpp).
#include <cmath>

#include <gtest/gtest.h>

#include "config/config_error.hpp"
#include "dynamics/conventions.hpp"
#include "gaits/impact/grid_range.hpp"

namespace gaitopt::gaits {
namespace {

TEST(GridRange, ARangeScaledToInternalUnits) {
  const GridAxis a = parseRange("1:60:60", "--knee-bias", kDeg);
  EXPECT_DOUBLE_EQ(a.first, kDeg);
  EXPECT_DOUBLE_EQ(a.last, 60 * kDeg);
  EXPECT_EQ(a.count, 60);
  EXPECT_DOUBLE_EQ(a.value(14), 15 * kDeg);
}

TEST(GridRange, OneValueIsARangeOfOne) {
  const GridAxis a = parseRange("0.35", "--step-lengths", 1.0);
  EXPECT_EQ(a.first, 0.35);
  EXPECT_EQ(a.last, 0.35);
  EXPECT_EQ(a.count, 1);
}

TEST(GridRange, MalformedRangesNameTheOption) {
  for (const char* bad :
       {"1:2", "1:2:0", "1:2:2.5", "1:2:2000001", "a:2:3", "1:2:3x", "nan", "1:inf:3", ""}) {
    try {
      parseRange(bad, "--approach-angles", 1.0);
      ADD_FAILURE() << "accepted '" << bad << "'";
    } catch (const config::ConfigError& e) {
      EXPECT_NE(std::string(e.what()).find("--approach-angles"), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace gaitopt::gaits
