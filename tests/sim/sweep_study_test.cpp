// A stability sweep's values and its walking interval (sim/studies/sweep_study.hpp), on made-up
// rows.
#include <cmath>

#include <gtest/gtest.h>

#include "sim/studies/sweep_study.hpp"

namespace gaitopt::sim {
namespace {

const SweepParameter kLinear{config::kPush, "hip impulse", -10, 10, 5, false};
const SweepParameter kGeometric{config::kStiffness, "ground stiffness", 1e4, 1e6, 3, true};

TEST(SweepValues, EvenlySpacedWithZeroExactlyOnTheGrid) {
  const auto v = sweepValues(kLinear, {-0.3, 0.5, 17});  // step 0.05: the 7th value is 0
  ASSERT_EQ(v.size(), 17u);
  EXPECT_DOUBLE_EQ(v.front(), -0.3);
  EXPECT_DOUBLE_EQ(v.back(), 0.5);
  EXPECT_EQ(v[6], 0.0);  // not 5.6e-17
  EXPECT_NEAR(v[1] - v[0], 0.05, 1e-15);
}

TEST(SweepValues, GeometricByAConstantRatio) {
  const auto v = sweepValues(kGeometric, {1e4, 1e6, 5});
  ASSERT_EQ(v.size(), 5u);
  for (std::size_t k = 0; k < v.size(); ++k)
    EXPECT_NEAR(v[k], std::pow(10.0, 4 + 0.5 * static_cast<double>(k)), 1e-9 * v[k]);
}

TEST(SweepValues, OneValueIsTheFirstEnd) {
  EXPECT_EQ(sweepValues(kGeometric, {2e5, 2e5, 1}), std::vector<double>{2e5});
}

// One rule for every sweep and map axis (push=0.5:0.5:3 wrote three
// rows of one point, push=1:-1:3 was accepted and push=-1:1:1 dropped 1 without a word).
TEST(SweepValues, ARangeRunsUpwards) {
  for (const gaits::GridAxis& bad : {gaits::GridAxis{0.5, 0.5, 3}, gaits::GridAxis{1, -1, 3},
                                     gaits::GridAxis{-1, 1, 1}, gaits::GridAxis{2e5, 1e5, 3}})
    for (const SweepParameter* p : {&kLinear, &kGeometric})
      EXPECT_THROW(sweepValues(*p, bad), std::invalid_argument)
          << p->name() << " " << bad.first << ":" << bad.last << ":" << bad.count;
  try {
    sweepValues(kLinear, {1, -1, 3});
    FAIL() << "a downward range was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(),
                 "'1:-1:3': 3 values need a < b (a range runs upwards); one value is a "
                 "or a:a:1");
  }
  EXPECT_EQ(sweepValues(kLinear, {0.5, 0.5, 1}), std::vector<double>{0.5});
  EXPECT_EQ(sweepValues(kLinear, {-1, 1, 2}), (std::vector<double>{-1, 1}));
}

// Values that share a row key's 10 digits would be one row (SweepFile::key).
TEST(SweepValues, ValuesCloserThanARowKeyAreRefused) {
  EXPECT_THROW(sweepValues(kLinear, {1, 1 + 1e-11, 3}), std::invalid_argument);
  EXPECT_NO_THROW(sweepValues(kLinear, {1, 1 + 1e-8, 3}));
}

TEST(SweepValues, AGeometricRangeNeedsPositiveEnds) {
  // Friction may be 0, so only the spacing refuses it here.
  const SweepParameter geometric_friction{config::kFriction, "friction", 0.1, 1, 3, true};
  EXPECT_THROW(sweepValues(geometric_friction, {0, 1, 3}), std::invalid_argument);
  EXPECT_NO_THROW(sweepValues(kLinear, {-1, 1, 3}));
}

TEST(SweepValues, EndsOutsideTheQuantityAreRefusedInItsWords) {
  try {
    sweepValues(kLinear, {-1e308, 1e308, 3});  // its middle value was NaN
    FAIL() << "an overflowing range was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "expected a number in [-1000, 1000] [N s], got -1e+308");
  }
  EXPECT_THROW(sweepValues(kLinear, {0, 1001, 3}), std::invalid_argument);
  EXPECT_THROW(sweepValues(kGeometric, {1e4, 1e13, 3}), std::invalid_argument);
}

TEST(SweepValues, EveryDefaultRangeIsInsideItsQuantity) {
  for (const SweepParameter& p : sweepParameters())
    EXPECT_NO_THROW(sweepValues(p, {p.first, p.last, p.count})) << p.name();
}

/// Rows keyed as SweepFile keys them; `fell` per value.
std::map<std::string, SweepRow> rows(const std::vector<std::pair<double, bool>>& walks) {
  std::map<std::string, SweepRow> out;
  for (const auto& [value, fell] : walks)
    out[SweepFile::key(value)] = {value, fell ? 3 : 10, 10, fell, fell ? "fall" : "", 0.01};
  return out;
}

TEST(WalkingInterval, IsTheRunOfWalkingValuesAroundTheNominalOne) {
  // Keys sort as text ("-10" < "-5" < "0" < "10" < "5"); the interval must sort by value.
  const auto j = walkingInterval(
      kLinear, rows({{-10, true}, {-5, false}, {0, false}, {5, false}, {10, true}}), 0.4);
  EXPECT_EQ(j.at("walks_from"), -5.0);
  EXPECT_EQ(j.at("walks_to"), 5.0);
  EXPECT_EQ(j.at("fails_below").at("value"), -10.0);
  EXPECT_EQ(j.at("fails_above").at("value"), 10.0);
  EXPECT_EQ(j.at("fails_above").at("failure"), "fall");
  EXPECT_EQ(j.at("values"), 5);
  EXPECT_EQ(j.at("unit"), "N s");
  // The picture's axis: a geometric parameter on a log axis even where the nominal inserted
  // breaks the constant ratio.
  EXPECT_EQ(j.at("geometric"), false);
  EXPECT_EQ(walkingInterval(kGeometric, rows({{1e5, false}, {3e5, false}, {1e7, false}}), 3e5)
                .at("geometric"),
            true);
}

// The ends are the grid's values as the CSV shows them (friction
// walks_from 0.30000000000000004, walks_to 0.9999999999999999, fails_above 0.05000000000000002).
TEST(WalkingInterval, EndsReadAsTheRowKeysWithoutRoundingNoise) {
  const double from = 0.1 + 0.2, to = 1 - 1e-16, above = 0.05000000000000002;
  ASSERT_NE(from, 0.3);
  const auto j = walkingInterval(
      kLinear, rows({{0.2, true}, {from, false}, {0.6, false}, {to, false}, {1.2, true}}), 0.6);
  EXPECT_EQ(j.at("walks_from").dump(), "0.3");
  EXPECT_EQ(j.at("walks_to").dump(), "1.0");
  EXPECT_EQ(j.at("fails_above").at("value").dump(), "1.2");
  const auto k = walkingInterval(kLinear, rows({{0, false}, {above, true}}), 0);
  EXPECT_EQ(k.at("fails_above").at("value").dump(), "0.05");
  EXPECT_EQ(keyedValue(above), 0.05);
}

TEST(WalkingInterval, NoneWhenTheNominalPointFalls) {
  const auto j = walkingInterval(kLinear, rows({{-5, false}, {0, true}, {5, false}}), 0.0);
  EXPECT_TRUE(j.at("walks_from").is_null());
  EXPECT_TRUE(j.at("walks_to").is_null());
  EXPECT_FALSE(j.contains("fails_below"));
  EXPECT_EQ(j.at("nominal_failure"), "fall");  // why there is no interval
}

TEST(WalkingInterval, NoneWithoutANominalValue) {
  const auto j = walkingInterval(kLinear, rows({{0, false}}), std::nan(""));
  EXPECT_TRUE(j.at("nominal").is_null());
  EXPECT_TRUE(j.at("walks_from").is_null());
}

// A grid that misses the nominal value gets it, in order, so the interval around it grows from a
// point that was walked; one that holds it (up to rounding) is kept as it is.
TEST(WithNominal, TheNominalValueIsOnTheGrid) {
  EXPECT_EQ(withNominal({-1.5, -0.5, 0.5, 1.5}, 0), (std::vector<double>{-1.5, -0.5, 0, 0.5, 1.5}));
  EXPECT_EQ(withNominal({0.2, 0.3, 0.4, 0.5}, 0.6), (std::vector<double>{0.2, 0.3, 0.4, 0.5, 0.6}));
  const std::vector<double> holds{0.1, 0.15000000000000002, 0.6000000000000001};
  EXPECT_EQ(withNominal(holds, 0.6), holds);
  EXPECT_EQ(withNominal(holds, std::nan("")), holds);
  // A nominal that shares a grid value's row key is that value: inserted, two points would
  // share one row.
  const std::vector<double> narrow{1000, 1001};  // keys "1000" and "1001"; 1e-9 of the span
  EXPECT_EQ(withNominal(narrow, 1000.0000001), narrow);
}

// A folder is keyed by what --set sets, not how it is typed (a rerun
// with its --set reordered, or 0.10 for 0.1, 1e-3 for 0.001, was refused).
TEST(SetsContent, KeyedByContentNotByText) {
  const auto key = setsContent({"robot.foot.heel=0.1", "ground.time_step=0.001"});
  EXPECT_EQ(key, setsContent({"ground.time_step=0.001", "robot.foot.heel=0.1"}));
  EXPECT_EQ(key, setsContent({"robot.foot.heel=0.10", "ground.time_step=1e-3"}));
  EXPECT_EQ(key.dump(), R"({"ground.time_step":0.001,"robot.foot.heel":0.1})");
  EXPECT_EQ(setsContent({"robot.foot={toe: 0.15, heel: 0.1}"}),
            setsContent({"robot.foot={heel: 0.10, toe: 1.5e-1}"}));
  EXPECT_EQ(setsContent({"robot.links[0].masses=[1, 2.0]"}),
            setsContent({"robot.links[0].masses=[1.0, 2]"}));
  // The last value of a key is the one the file gets.
  EXPECT_EQ(setsContent({"robot.friction=0.3", "robot.friction=0.5"}),
            setsContent({"robot.friction=0.5"}));
}

TEST(SetsContent, OtherValuesAndOrdersThatMatterDiffer) {
  EXPECT_NE(setsContent({"robot.foot.heel=0.1"}), setsContent({"robot.foot.heel=0.11"}));
  EXPECT_NE(setsContent({"robot.foot.heel=0.1"}), setsContent({"robot.foot.toe=0.1"}));
  EXPECT_NE(setsContent({"robot.friction=0.5", "robot.friction=0.3"}),
            setsContent({"robot.friction=0.3", "robot.friction=0.5"}));
  EXPECT_NE(setsContent({"ground.model=pad"}), setsContent({"ground.model=impedance"}));
  // A key inside another's value: the later one wins, so the order stays.
  EXPECT_NE(setsContent({"robot.foot={heel: 0.1, toe: 0.15}", "robot.foot.heel=0.2"}),
            setsContent({"robot.foot.heel=0.2", "robot.foot={heel: 0.1, toe: 0.15}"}));
}

}  // namespace
}  // namespace gaitopt::sim
