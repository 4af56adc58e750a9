// The table of quantities (config/quantities.hpp): every entry has finite bounds, a unit unless a
// pure number on purpose, and one name; each check takes both ends, refuses what lies beyond
// them, NaN and Inf, and words its refusal with the range, the unit and the value.
#include <cmath>
#include <limits>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "config/config_error.hpp"
#include "config/quantities.hpp"
#include "config/yaml_reader.hpp"

namespace gaitopt::config {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(Quantities, FiniteBoundsAUnitAndOneName) {
  const std::set<std::string_view> pure_numbers{"mass_error", "length_error", "friction",
                                                "gain_scale", "steps"};
  std::set<std::string_view> names;
  for (const Quantity& q : kQuantities) {
    EXPECT_TRUE(std::isfinite(q.lo) && std::isfinite(q.hi)) << q.name;
    EXPECT_LT(q.lo, q.hi) << q.name;
    EXPECT_NE(q.unit.empty(), pure_numbers.count(q.name) == 0) << q.name << " [" << q.unit << "]";
    EXPECT_TRUE(names.insert(q.name).second) << q.name << " twice";
  }
}

TEST(Quantities, BothEndsInsideEverythingElseOutside) {
  for (const Quantity& q : kQuantities) {
    EXPECT_EQ(rangeError(q, q.lo), "") << q.name;
    EXPECT_EQ(rangeError(q, q.hi), "") << q.name;
    for (const double outside :
         {std::nextafter(q.lo, -kInf), std::nextafter(q.hi, kInf), -kInf, kInf, std::nan("")})
      EXPECT_NE(rangeError(q, outside), "") << q.name << " took " << outside;
  }
}

TEST(Quantities, TheRefusalNamesRangeUnitValueAndSource) {
  EXPECT_EQ(rangeError(kSampleRate, 1e20), "expected a number in [1, 1e+06] [Hz], got 1e+20");
  EXPECT_EQ(rangeError(kMassError, -2), "expected a number in [-0.5, 2], got -2");
  try {
    requireInRange(kLinkRate, 1e308, "state.json", "dtheta[0]");
    FAIL() << "1e308 rad/s accepted";
  } catch (const ConfigError& e) {
    EXPECT_EQ(e.key(), "dtheta[0]");
    EXPECT_STREQ(e.what(),
                 "state.json: key 'dtheta[0]': expected a number in [-1000, 1000] [rad/s], got "
                 "1e+308");
  }
  EXPECT_EQ(requireInRange(kSteps, 3, "steps"), 3);
}

TEST(Quantities, AConfigKeyIsCheckedAsTheSameQuantityElsewhere) {
  const NumberCheck check = inRange(kStiffness);
  EXPECT_EQ(check(1e7), "");
  EXPECT_EQ(check(0), "a number in [100, 1e+12] [N/m^n]");
  EXPECT_EQ(check(0), expectation(kStiffness));
}

}  // namespace
}  // namespace gaitopt::config
