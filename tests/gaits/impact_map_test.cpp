// The impact-type map of Mu (2004) sec. 5.3: parallel sweep, grid checks, and the region
// statements of the thesis (Figs. 5.2, 5.3, 5.5, 5.7; docs/derivations.md#impact-regions).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "gaits/impact/impact_map.hpp"
#include "support/fixtures.hpp"

namespace gaitopt::test {
namespace {

using dynamics::ImpactType;
using gaits::GridAxis;
using gaits::ImpactGrid;
using gaits::MapAxis;

ImpactGrid grid(GridAxis step, GridAxis sigma_deg, GridAxis alpha_deg) {
  sigma_deg.first *= kDeg;
  sigma_deg.last *= kDeg;
  alpha_deg.first *= kDeg;
  alpha_deg.last *= kDeg;
  return {{step, sigma_deg, alpha_deg}, 1.0};
}

GridAxis one(double v) {
  return {v, v, 1};
}

class ImpactMapTest : public ::testing::Test {
 protected:
  dynamics::Model model_ = loadNamed("mu2004_five_link");

  /// Boundary along the step length (alpha = 90 deg) where the type first leaves `type` [m];
  /// NaN when it never does. Mu's S_L is twice this.
  double firstChangeFrom(ImpactType type, double sigma_deg) {
    const auto map =
        gaits::sweepImpactMap(model_, grid({0.025, 1.0, 40}, one(sigma_deg), one(90)), 1);
    for (const auto& c : gaits::typeChangesAlong(map, MapAxis::kStepLength, {0, 0, 0}))
      if (c.from == type) return c.at;
    return NAN;
  }
};

TEST_F(ImpactMapTest, SweepDoesNotDependOnTheNumberOfJobs) {
  const ImpactGrid g = grid({0.1, 0.95, 6}, {1, 60, 5}, {5, 175, 7});
  size_t last_done = 0;
  const auto serial = gaits::sweepImpactMap(model_, g, 1);
  const auto parallel =
      gaits::sweepImpactMap(model_, g, 3, [&](size_t done, size_t) { last_done = done; });
  EXPECT_EQ(last_done, g.size());
  ASSERT_EQ(parallel.points.size(), g.size());
  for (size_t i = 0; i < g.size(); ++i) {
    const auto& a = serial.points[i];
    const auto& b = parallel.points[i];
    EXPECT_EQ(a.params.step_length, b.params.step_length);
    EXPECT_EQ(a.params.approach_angle, b.params.approach_angle);
    EXPECT_EQ(a.type, b.type);
    EXPECT_EQ(a.double_model.impulse_trailing, b.double_model.impulse_trailing);
    EXPECT_EQ(a.single_model.trailing_velocity, b.single_model.trailing_velocity);
  }
  // Grid order: alpha fastest, step length slowest.
  EXPECT_DOUBLE_EQ(serial.at({1, 2, 3}).params.step_length, 0.1 + 0.85 / 5);
  EXPECT_DOUBLE_EQ(serial.at({1, 2, 3}).params.approach_angle, 90 * kDeg);
}

// Mu's open question (ch. 5, sec. 6.2): where his sticking models are both consistent
// ('either') or neither is, which impact happens? The complementarity law over both tips with
// Coulomb friction (mu 0.6, plastic) has one family of solutions at every point of his map:
// it decides them all, and where his choice keeps its own friction condition (and, for a double
// impact, pushes at both tips) it agrees.
TEST_F(ImpactMapTest, TheComplementarityLawDecidesMusEitherAndNeitherRegions) {
  const auto map =
      gaits::sweepImpactMap(model_, grid({0.025, 1.0, 40}, {1, 60, 12}, {5, 175, 18}), 2);
  int either = 0, neither = 0;
  for (const auto& p : map.points) {
    ASSERT_TRUE(p.lcp_type == ImpactType::kSingle || p.lcp_type == ImpactType::kDouble)
        << dynamics::toString(p.lcp_type) << " at step " << p.params.step_length;
    either += p.type == ImpactType::kEither;
    neither += p.type == ImpactType::kNeither;
    // Mu's double criterion (2.31a) asks B's impulse to push, not E's: at grazing approaches
    // his double impact pulls E into the ground (P_ry < 0), which the law refuses.
    const bool e_pushes = p.double_model.impulse_leading(1) > 0;
    if (p.type == ImpactType::kDouble && p.double_model.friction_ok && e_pushes) {
      EXPECT_EQ(p.lcp_type, ImpactType::kDouble);
    }
    if (p.type == ImpactType::kSingle && p.single_model.friction_ok) {
      EXPECT_EQ(p.lcp_type, ImpactType::kSingle);
    }
  }
  EXPECT_GT(either, 50);
  EXPECT_GT(neither, 10);
}

TEST_F(ImpactMapTest, RejectsBadGrids) {
  const GridAxis step{0.1, 0.9, 5}, sigma{1, 60, 5}, alpha{5, 175, 5};
  for (const ImpactGrid& bad :
       {grid({0.1, 0.9, 0}, sigma, alpha), grid({NAN, 0.9, 5}, sigma, alpha),
        grid({0.9, 0.1, 5}, sigma, alpha), grid({0.1, 0.9, 1}, sigma, alpha),
        grid({0.0, 0.9, 5}, sigma, alpha), grid(step, {0, 60, 5}, alpha),
        grid(step, {1, 180, 5}, alpha), grid(step, sigma, {0, 175, 5}),
        grid(step, sigma, {5, 180, 5}), grid({0.1, 1.2, 5}, sigma, alpha)})
    EXPECT_THROW(gaits::checkImpactGrid(model_, bad), std::invalid_argument);
  EXPECT_THROW(gaits::sweepImpactMap(model_, grid(step, sigma, alpha), 0), std::invalid_argument);
  EXPECT_NO_THROW(gaits::checkImpactGrid(model_, grid(step, sigma, alpha)));
}

TEST_F(ImpactMapTest, ShortStepsGiveOnlySingleImpactAtSigma15) {
  // Fig. 5.3(a): sigma 15 deg, S_L up to 1.4 m, alpha 20-150 deg -> only single impact. Our
  // boundary lies at S_L 1.35 (below), so the check stops at S_L 1.3 (step_length 0.65).
  const auto map = gaits::sweepImpactMap(model_, grid({0.05, 0.65, 13}, one(15), {20, 150, 27}), 2);
  for (const auto& p : map.points) EXPECT_EQ(p.type, ImpactType::kSingle);
}

TEST_F(ImpactMapTest, LongerStepsTurnSingleIntoDoubleNearMusBoundary) {
  // Fig. 5.3(a), sigma 15, alpha 90: single below S_L ~1.4 m, double at long steps, with the
  // 'both may occur' band of Fig. 5.2 between them (docs/derivations.md#impact-regions).
  const auto map = gaits::sweepImpactMap(model_, grid({0.025, 1.0, 40}, one(15), one(90)), 1);
  const auto changes = gaits::typeChangesAlong(map, MapAxis::kStepLength, {0, 0, 0});
  ASSERT_EQ(changes.size(), 2u);
  EXPECT_EQ(changes[0].from, ImpactType::kSingle);
  EXPECT_EQ(changes[0].to, ImpactType::kEither);
  EXPECT_NEAR(2 * changes[0].at, 1.4, 0.1);
  EXPECT_EQ(changes[1].to, ImpactType::kDouble);
  EXPECT_GT(changes[1].at, changes[0].at);
}

TEST_F(ImpactMapTest, LongStepsGiveDoubleImpactOnlyForSmallKneeBias) {
  // Fig. 5.3(d), S_L 1.8 m: double impact for sigma < 20 deg over a wide alpha range (thesis:
  // 40-180 deg; here from 44 deg at sigma 5 and 41 deg at sigma 15, results/impact_sensitivity),
  // checked from 55 deg on, and none at larger sigma.
  for (double sigma : {1.0, 5.0, 10.0, 15.0}) {
    const auto map = gaits::sweepImpactMap(model_, grid(one(0.9), one(sigma), {55, 175, 25}), 1);
    for (const auto& p : map.points)
      EXPECT_EQ(p.type, ImpactType::kDouble) << sigma << " deg, " << p.params.approach_angle / kDeg;
  }
  for (double sigma : {25.0, 40.0})
    EXPECT_NE(gaits::evaluateImpactPoint(model_, {0.9, sigma * kDeg, 90 * kDeg, 1}).type,
              ImpactType::kDouble);
}

TEST_F(ImpactMapTest, SingleRegionBoundaryMovesToLongerStepsAsTheKneeBends) {
  // Sec. 5.3.2: positive P_ly and ydot_b+ decrease as sigma grows, so the step length where
  // P_ly turns positive (single -> either/double) and where the double region starts both move to
  // longer steps as sigma grows, and the double region is gone from sigma ~20 deg on.
  double previous = 0;
  for (double sigma : {1.0, 10.0, 20.0, 30.0, 40.0}) {
    const double at = firstChangeFrom(ImpactType::kSingle, sigma);
    EXPECT_GE(at, previous) << sigma;
    previous = at;
  }
  EXPECT_GT(previous, firstChangeFrom(ImpactType::kSingle, 1.0) + 0.2);
  EXPECT_LT(firstChangeFrom(ImpactType::kEither, 1.0), firstChangeFrom(ImpactType::kEither, 15.0));
  EXPECT_TRUE(std::isnan(firstChangeFrom(ImpactType::kEither, 25.0)));  // '.' to the end
}

TEST_F(ImpactMapTest, ShortStepDoubleRegionGrowsWithKneeBias) {
  // Region II (Fig. 5.5) and the Hurmuzlu agreement of sec. 5.3.3: for short steps double impact
  // is more likely with large sigma and large alpha. At S_L 0.1 m the alpha where double impact
  // begins falls as sigma grows, staying above 145 deg (region II: alpha > 150).
  double previous = std::numbers::pi;
  for (double sigma : {15.0, 30.0, 45.0, 60.0}) {
    const auto map =
        gaits::sweepImpactMap(model_, grid(one(0.05), one(sigma), {90, 180 - 1e-9, 91}), 1);
    const auto changes = gaits::typeChangesAlong(map, MapAxis::kApproachAngle, {0, 0, 0});
    ASSERT_FALSE(changes.empty()) << sigma;
    const double at = changes.back().at;
    EXPECT_EQ(changes.back().to, ImpactType::kDouble);
    EXPECT_LT(at, previous) << sigma;
    EXPECT_GT(at, 145 * kDeg);
    previous = at;
  }
}

TEST_F(ImpactMapTest, SingleImpactFrictionRatioIsModerateInTheFlatRegion) {
  // Fig. 5.7: for 50 < alpha < 140 deg and S_L <= 1.35 m, |mu_S| stays under ~0.5 (here at
  // most 0.58, docs/derivations.md#impact-regions); for alpha > 140 deg and S_L < 0.5 m it rises
  // sharply (sigma >= 20).
  for (double sigma : {1.0, 20.0, 40.0, 60.0}) {
    const auto flat =
        gaits::sweepImpactMap(model_, grid({0.05, 0.675, 26}, one(sigma), {55, 135, 17}), 1);
    for (const auto& p : flat.points)
      if (p.type == ImpactType::kSingle) {
        EXPECT_LT(std::abs(p.mu_s), 0.6);
      }
    const auto steep =
        gaits::sweepImpactMap(model_, grid({0.05, 0.2, 4}, one(sigma), {145, 175, 7}), 1);
    double worst = 0;
    for (const auto& p : steep.points) worst = std::max(worst, std::abs(p.mu_s));
    if (sigma >= 20) {
      EXPECT_GT(worst, 10.0) << sigma;
    }
  }
}

}  // namespace
}  // namespace gaitopt::test
