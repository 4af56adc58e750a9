// Impacts with Coulomb friction and Newton restitution (Hurmuzlu, Genot, Brogliato 2001 sec.
// 3.3.2 and eqs. 76-82): the rigid map inside the cone, and outside it an impulse on the cone
// boundary that leaves the tip sliding against it, with the conservation laws that must hold.
#include <gtest/gtest.h>

#include <Eigen/LU>

#include "dynamics/energy.hpp"
#include "dynamics/impact/frictional_impact.hpp"
#include "dynamics/impact/impact.hpp"
#include "dynamics/kinematics.hpp"
#include "dynamics/model_variation.hpp"
#include "support/fixtures.hpp"
#include "support/impulse_at_tip.hpp"

namespace gaitopt::test {
namespace {

using dynamics::FrictionalImpact;
using dynamics::Model;
using dynamics::TipImpact;

double kinetic(const Model& m, const VecD& theta, const VecD& dtheta, const Vec2d& base) {
  return dynamics::kineticEnergy<double>(m, theta, dtheta, base);
}

/// Coulomb's law at impulse level at one tip (HGB 79-81) and the plastic normal law (76-78).
void expectCoulomb(const TipImpact& tip, double mu) {
  const double scale = 1e-12 * (1 + tip.impulse.norm());
  EXPECT_GE(tip.impulse(1), -scale);
  EXPECT_NEAR(tip.velocity(1), 0.0, 1e-12 * (1 + tip.velocity.norm()));
  if (!tip.slides) {
    EXPECT_LE(std::abs(tip.impulse(0)), mu * tip.impulse(1) + scale);
    EXPECT_NEAR(tip.velocity(0), 0.0, 1e-12);
    return;
  }
  EXPECT_NEAR(std::abs(tip.impulse(0)), mu * tip.impulse(1), scale);  // on the cone boundary
  EXPECT_LT(tip.impulse(0) * tip.velocity(0), 0.0);  // the impulse opposes the slip it leaves
}

class FrictionalImpactTest : public ::testing::TestWithParam<std::string> {
 protected:
  Model model_ = loadNamed(GetParam());
  std::mt19937 rng_{11};
};

class FrictionalDoubleImpactTest : public FrictionalImpactTest {};

TEST_P(FrictionalImpactTest, InsideTheConeItIsTheRigidMap) {
  const Model sticky = dynamics::withFriction(model_, 5.0);
  int compared = 0;
  for (int trial = 0; trial < 50; ++trial) {
    const auto [theta, dtheta] = preImpact(sticky, rng_);
    const auto rigid = dynamics::singleImpact(sticky, theta, dtheta);
    if (rigid.friction_ok && rigid.impulse_leading(1) > 0) {
      const FrictionalImpact f = dynamics::frictionalSingleImpact(sticky, theta, dtheta, 0.0);
      EXPECT_FALSE(f.leading.slides);
      EXPECT_LT(relErr(f.dtheta_plus, rigid.dtheta_plus, 1.0), 1e-12);
      EXPECT_LT(relErr(f.leading.impulse, rigid.impulse_leading, 1.0), 1e-12);
      EXPECT_LT(relErr(f.base_velocity, rigid.trailing_velocity, 1.0), 1e-12);
      ++compared;
    }
    const auto both = dynamics::doubleImpact(sticky, theta, dtheta);
    if (both.friction_ok && both.unilateral_ok && both.impulse_leading(1) > 0) {
      const FrictionalImpact f = dynamics::frictionalDoubleImpact(sticky, theta, dtheta, 0.0);
      EXPECT_FALSE(f.leading.slides || f.trailing.slides);
      EXPECT_LT(relErr(f.dtheta_plus, both.dtheta_plus, 1.0), 1e-12);
      EXPECT_LT(relErr(f.trailing.impulse, both.impulse_trailing, 1.0), 1e-12);
      EXPECT_LT(relErr(f.leading.impulse, both.impulse_leading, 1.0), 1e-12);
      ++compared;
    }
  }
  EXPECT_GT(compared, 25);
}

TEST_P(FrictionalImpactTest, SingleImpactOutsideTheConeSlidesAndConservesMomentumAboutE) {
  const Model slippery = dynamics::withFriction(model_, 0.05);
  int slid = 0;
  for (int trial = 0; trial < 50; ++trial) {
    const auto [theta, dtheta] = preImpact(slippery, rng_);
    if (dynamics::singleImpact(slippery, theta, dtheta).friction_ok) continue;
    const FrictionalImpact f = dynamics::frictionalSingleImpact(slippery, theta, dtheta, 0.0);
    ASSERT_TRUE(f.consistent);
    EXPECT_TRUE(f.leading.slides);
    expectCoulomb(f.leading, 0.05);
    EXPECT_LE(kinetic(slippery, theta, f.dtheta_plus, f.base_velocity),
              kinetic(slippery, theta, dtheta, Vec2d::Zero()) + 1e-12);
    // The only impulse acts at E, sliding or not.
    expectImpulseAtSwingTipOnly(slippery, theta, dtheta, f.dtheta_plus, f.base_velocity,
                                f.leading.impulse, 1e-10);
    ++slid;
  }
  EXPECT_GT(slid, 5);
}

TEST_P(FrictionalDoubleImpactTest, DoubleImpactObeysCoulombAtBothTipsAndDissipates) {
  const Model slippery = dynamics::withFriction(model_, 0.02);
  int slid = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const auto [theta, dtheta] = preImpact(slippery, rng_);
    const FrictionalImpact f = dynamics::frictionalDoubleImpact(slippery, theta, dtheta, 0.0);
    if (!f.consistent) continue;  // a sticking impulse pulls a tip: not a double impact
    expectCoulomb(f.trailing, 0.02);
    expectCoulomb(f.leading, 0.02);
    EXPECT_LE(kinetic(slippery, theta, f.dtheta_plus, f.base_velocity),
              kinetic(slippery, theta, dtheta, Vec2d::Zero()) + 1e-12);
    const Vec2d dp =
        dynamics::linearMomentum<double>(slippery, theta, f.dtheta_plus, f.base_velocity) -
        dynamics::linearMomentum<double>(slippery, theta, dtheta);
    EXPECT_LT((f.leading.impulse + f.trailing.impulse - dp).norm(), 1e-10 * (1 + dp.norm()));
    slid += f.leading.slides || f.trailing.slides;
  }
  EXPECT_GT(slid, 5);
}

TEST_P(FrictionalImpactTest, FrictionlessGroundTakesNoTangentialImpulse) {
  const Model ice = dynamics::withFriction(model_, 0.0);
  for (int trial = 0; trial < 20; ++trial) {
    const auto [theta, dtheta] = preImpact(ice, rng_);
    const FrictionalImpact f = dynamics::frictionalSingleImpact(ice, theta, dtheta, 0.0);
    ASSERT_TRUE(f.consistent);
    EXPECT_NEAR(f.leading.impulse(0), 0.0, 1e-12);
    // No horizontal impulse: horizontal momentum is conserved.
    EXPECT_NEAR(dynamics::linearMomentum<double>(ice, theta, f.dtheta_plus, f.base_velocity)(0),
                dynamics::linearMomentum<double>(ice, theta, dtheta)(0), 1e-10);
  }
}

TEST_P(FrictionalImpactTest, NewtonRestitutionReversesTheNormalVelocity) {
  for (double mu : {5.0, 0.05}) {
    const Model m = dynamics::withFriction(model_, mu);
    for (int trial = 0; trial < 20; ++trial) {
      const auto [theta, dtheta] = preImpact(m, rng_);
      const double vn = (dynamics::pointJacobian(m.tipWeights(), theta) * dtheta)(1);
      const FrictionalImpact f = dynamics::frictionalSingleImpact(m, theta, dtheta, 0.3);
      ASSERT_TRUE(f.consistent);
      EXPECT_NEAR(f.leading.velocity(1), -0.3 * vn, 1e-12 * (1 + std::abs(vn)));
    }
  }
}

INSTANTIATE_TEST_SUITE_P(AllRobots, FrictionalImpactTest, ::testing::ValuesIn(allRobots()));
// RABBIT is left out: in random postures its sticking double impact always pulls one tip (P_By
// or P_Ey < 0, Mu 2.31a), so it never has a double impact to test.
INSTANTIATE_TEST_SUITE_P(DoubleImpactRobots, FrictionalDoubleImpactTest,
                         ::testing::Values("mu2004_five_link", "three_link", "compass_gait"));

/// Mu's reference impact, S_L = 0.7 m, a vertical strike at 1 m/s
/// (docs/derivations.md#impact-reference-values; impact_test.cpp). The sticking single impact
/// needs |P_x / P_y| = 0.115 (1.3560 / 11.7933).
class MuSlidingImpact : public ::testing::Test {
 protected:
  VecD theta_ = (VecD(5) << 23.3079, 8.3079, 0, 155.9782, 170.9782).finished() * kDeg;
  VecD dtheta(const Model& m) const {
    const Mat2Xd jac = dynamics::pointJacobian(m.tipWeights(), theta_);
    return VecD(jac.transpose() * (jac * jac.transpose()).inverse() * Vec2d(0, -1));
  }
};

TEST_F(MuSlidingImpact, BelowTheNeededFrictionTheTipSlidesForward) {
  const Model m = dynamics::withFriction(loadNamed("mu2004_five_link"), 0.05);
  const FrictionalImpact f = dynamics::frictionalSingleImpact(m, theta_, dtheta(m), 0.0);
  ASSERT_TRUE(f.consistent);
  ASSERT_TRUE(f.leading.slides);
  // The sticking impulse pushes back (P_x < 0), so the sliding tip moves forward against it.
  EXPECT_NEAR(f.leading.impulse(0), -0.05 * f.leading.impulse(1), 1e-12);
  EXPECT_GT(f.leading.velocity(0), 0.0);
  EXPECT_TRUE(f.unilateral_ok);
}

TEST_F(MuSlidingImpact, AtTheNeededFrictionItSticks) {
  const Model m = dynamics::withFriction(loadNamed("mu2004_five_link"), 0.12);
  const FrictionalImpact f = dynamics::frictionalSingleImpact(m, theta_, dtheta(m), 0.0);
  EXPECT_FALSE(f.leading.slides);
  EXPECT_NEAR(f.leading.impulse(0), -1.3560, 2e-3);
  EXPECT_NEAR(f.leading.impulse(1), 11.7933, 2e-3);
}

// The impact as one complementarity problem over both tips (complementarityImpact): every
// solution it returns keeps Signorini's law at B (an impulse only while B stays, B never moving
// into the ground), the plastic law at E, Coulomb's law at every tip in contact, and does not
// create energy.
TEST_P(FrictionalImpactTest, EveryComplementaritySolutionKeepsSignoriniCoulombAndEnergy) {
  int solutions = 0;
  for (int trial = 0; trial < 60; ++trial) {
    const auto [theta, dtheta] = preImpact(model_, rng_);
    const auto c = dynamics::complementarityImpact(model_, theta, dtheta, 0.0);
    const double before = kinetic(model_, theta, dtheta, Vec2d::Zero());
    for (const FrictionalImpact& f : c.staying) {
      expectCoulomb(f.trailing, model_.friction());
      expectCoulomb(f.leading, model_.friction());
      EXPECT_LE(kinetic(model_, theta, f.dtheta_plus, f.base_velocity), before * (1 + 1e-12));
    }
    for (const FrictionalImpact& f : c.leaving) {
      EXPECT_GE(f.base_velocity(1), -1e-12 * (1 + f.base_velocity.norm()));  // B lifts or rests
      EXPECT_EQ(f.trailing.impulse, Vec2d::Zero());
      expectCoulomb(f.leading, model_.friction());
      EXPECT_LE(kinetic(model_, theta, f.dtheta_plus, f.base_velocity), before * (1 + 1e-12));
    }
    solutions += static_cast<int>(c.staying.size() + c.leaving.size());
  }
  EXPECT_GT(solutions, 30);
}

// Without friction the plastic impact over both tips is a complementarity problem in the normal
// impulses whose matrix (the Delassus matrix) is positive definite, so it has exactly one
// solution: the law decides single or double everywhere, never 'either' or 'neither'. Each tip
// slides, whichever way its tangential velocity leaves it.
TEST_P(FrictionalImpactTest, WithoutFrictionTheLawHasExactlyOneSolution) {
  const Model slippery = dynamics::withFriction(model_, 1e-6);
  for (int trial = 0; trial < 100; ++trial) {
    const auto [theta, dtheta] = preImpact(slippery, rng_);
    const auto c = dynamics::complementarityImpact(slippery, theta, dtheta, 0.0);
    EXPECT_EQ(c.staying.size() + c.leaving.size(), 1u) << "trial " << trial;
  }
}

}  // namespace
}  // namespace gaitopt::test
