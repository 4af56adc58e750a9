// Rigid impact maps (Mu 2.23-2.37) against the floating-base impulse solution, conservation
// laws, and the reference numbers of docs/derivations.md#impact-reference-values.
#include <gtest/gtest.h>

#include "dynamics/energy.hpp"
#include "dynamics/floating_base.hpp"
#include "dynamics/impact/impact.hpp"
#include "dynamics/kinematics.hpp"
#include "support/fixtures.hpp"
#include "support/floating_base.hpp"
#include "support/impulse_at_tip.hpp"

namespace gaitopt::test {
namespace {

using dynamics::Model;

/// Floating-base impulse problem: mass dq = J^T P, J q+ = 0 for the given contact rows.
std::pair<Eigen::VectorXd, Eigen::VectorXd> floatingImpact(const Model& m, const VecD& theta,
                                                           const VecD& dtheta, bool both) {
  const int n = m.nLinks();
  const FloatingBase fb = floatingBase(m, theta, dtheta);
  Eigen::VectorXd qdot_minus = Eigen::VectorXd::Zero(n + 2);
  qdot_minus.tail(n) = dtheta;  // B at rest before impact
  Eigen::MatrixXd jac = both ? Eigen::MatrixXd(4, n + 2) : fb.jac_e;
  if (both) jac << fb.jac_b, fb.jac_e;
  // mass (q+ - q-) = J^T P and J q+ = 0  <=>  KKT with rhs mass q-.
  const auto [qplus, impulses] =
      solveKkt(fb.mass, fb.mass * qdot_minus, jac, Eigen::VectorXd::Zero(jac.rows()));
  return {qplus, impulses};
}

class ImpactTest : public ::testing::TestWithParam<std::string> {
 protected:
  Model model_ = loadNamed(GetParam());
  std::mt19937 rng_{3};
};

TEST_P(ImpactTest, DoubleImpactMatchesFloatingBaseAndStopsBothTips) {
  const int n = model_.nLinks();
  for (int trial = 0; trial < 50; ++trial) {
    const auto [theta, dtheta] = preImpact(model_, rng_);
    const auto r = dynamics::doubleImpact(model_, theta, dtheta);
    const auto [qplus, impulses] = floatingImpact(model_, theta, dtheta, true);
    EXPECT_LT(relErr(r.dtheta_plus, VecD(qplus.tail(n)), 1.0), 1e-9);
    EXPECT_LT(relErr(r.impulse_trailing, Vec2d(impulses.head<2>()), 1.0), 1e-9);
    EXPECT_LT(relErr(r.impulse_leading, Vec2d(impulses.tail<2>()), 1.0), 1e-9);
    EXPECT_LT((dynamics::pointJacobian(model_.tipWeights(), theta) * r.dtheta_plus).norm(), 1e-10);
    // Impulse-momentum balance: P_l + P_r = change of total linear momentum.
    const Vec2d dp = dynamics::linearMomentum<double>(model_, theta, r.dtheta_plus) -
                     dynamics::linearMomentum<double>(model_, theta, dtheta);
    EXPECT_LT((r.impulse_trailing + r.impulse_leading - dp).norm(), 1e-9 * (1 + dp.norm()));
    EXPECT_LE(dynamics::kineticEnergy<double>(model_, theta, r.dtheta_plus),
              dynamics::kineticEnergy<double>(model_, theta, dtheta) + 1e-12);
  }
}

TEST_P(ImpactTest, SingleImpactMatchesFloatingBaseAndConservesMomentumAboutE) {
  const int n = model_.nLinks();
  for (int trial = 0; trial < 50; ++trial) {
    const auto [theta, dtheta] = preImpact(model_, rng_);
    const auto r = dynamics::singleImpact(model_, theta, dtheta);
    const auto [qplus, impulses] = floatingImpact(model_, theta, dtheta, false);
    EXPECT_LT(relErr(r.dtheta_plus, VecD(qplus.tail(n)), 1.0), 1e-9);
    EXPECT_LT(relErr(r.trailing_velocity, Vec2d(qplus.head<2>()), 1.0), 1e-9);
    EXPECT_LT(relErr(r.impulse_leading, Vec2d(impulses), 1.0), 1e-9);
    EXPECT_EQ(r.impulse_trailing.norm(), 0.0);
    // E stops: base velocity plus relative tip velocity.
    const Vec2d tip_after =
        r.trailing_velocity + dynamics::pointJacobian(model_.tipWeights(), theta) * r.dtheta_plus;
    EXPECT_LT(tip_after.norm(), 1e-10);
    // Angular momentum about E and the impulse-momentum balance (the only impulse acts at E).
    expectImpulseAtSwingTipOnly(model_, theta, dtheta, r.dtheta_plus, r.trailing_velocity,
                                r.impulse_leading, 1e-9);
  }
}

TEST_P(ImpactTest, ClosedFormsSatisfyTheImplicitImpactResidual) {
  // The optimiser's implicit form (floating_base.hpp) vanishes at Mu's closed-form solutions.
  const int n = model_.nLinks();
  for (int trial = 0; trial < 20; ++trial) {
    const auto [theta, dtheta] = preImpact(model_, rng_);
    const auto s = dynamics::singleImpact(model_, theta, dtheta);
    Eigen::VectorXd qplus(n + 2);
    qplus << s.trailing_velocity, s.dtheta_plus;
    EXPECT_LT(
        dynamics::impactResidual<double>(model_, theta, dtheta, qplus, s.impulse_leading, nullptr)
            .norm(),
        1e-9);
    const auto d = dynamics::doubleImpact(model_, theta, dtheta);
    qplus << 0, 0, d.dtheta_plus;
    const Vec2d p_b = d.impulse_trailing;
    EXPECT_LT(
        dynamics::impactResidual<double>(model_, theta, dtheta, qplus, d.impulse_leading, &p_b)
            .norm(),
        1e-9);
  }
}

TEST_P(ImpactTest, ZeroTipVelocityGivesNoImpulse) {
  // Mu sec. 9 fact 16: the ch. 3 gait lands with zero tip velocity, so rates are continuous.
  for (int trial = 0; trial < 20; ++trial) {
    const auto [theta, dtheta_any] = preImpact(model_, rng_);
    const int n = model_.nLinks();
    const Mat2Xd jac = dynamics::pointJacobian(model_.tipWeights(), theta);
    const Eigen::MatrixXd proj =
        Eigen::MatrixXd::Identity(n, n) - jac.transpose() * (jac * jac.transpose()).inverse() * jac;
    const VecD dtheta = proj * Eigen::VectorXd(dtheta_any);
    for (const auto& r : {dynamics::doubleImpact(model_, theta, dtheta),
                          dynamics::singleImpact(model_, theta, dtheta)}) {
      EXPECT_LT((r.dtheta_plus - dtheta).norm(), 1e-10);
      EXPECT_LT(r.impulse_leading.norm() + r.impulse_trailing.norm(), 1e-9);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(AllRobots, ImpactTest, ::testing::ValuesIn(allRobots()));

/// Mu's reference impact, S_L = 0.7 m, sigma = 15 deg, alpha = 90 deg, V_e = 1 m/s,
/// I_i = 0.033 kg m^2 (docs/derivations.md#impact-reference-values). Impulses depend on Xdot_e^-
/// only, so any dtheta^- with that tip velocity serves; we take the Euclidean minimum-norm one.
class MuReferenceImpact : public ::testing::Test {
 protected:
  Model model_ = loadNamed("mu2004_five_link");
  VecD theta_ = (VecD(5) << 23.3079, 8.3079, 0, 155.9782, 170.9782).finished() * kDeg;
  VecD dtheta_ = [this] {
    const Mat2Xd jac = dynamics::pointJacobian(model_.tipWeights(), theta_);
    return VecD(jac.transpose() * (jac * jac.transpose()).inverse() * Vec2d(0, -1));
  }();
};

TEST_F(MuReferenceImpact, PostureHasTheStatedGeometry) {
  EXPECT_NEAR(dynamics::hip(model_, theta_)(0), 0.175, 1e-4);
  EXPECT_NEAR(dynamics::hip(model_, theta_)(1), 0.60374, 1e-4);
  EXPECT_NEAR(dynamics::swingTip(model_, theta_)(0), 0.35, 1e-4);
  EXPECT_NEAR(dynamics::swingTip(model_, theta_)(1), 0.0, 1e-4);
}

TEST_F(MuReferenceImpact, DoubleImpactImpulses) {
  const auto r = dynamics::doubleImpact(model_, theta_, dtheta_);
  EXPECT_NEAR(r.impulse_trailing(0), -1.6583, 2e-3);
  EXPECT_NEAR(r.impulse_trailing(1), -3.6015, 2e-3);
  EXPECT_NEAR(r.impulse_leading(0), -1.4634, 2e-3);
  EXPECT_NEAR(r.impulse_leading(1), 12.8014, 2e-3);
  const VecD delta = r.dtheta_plus - dtheta_;
  const VecD expected = (VecD(5) << -1.1926, -1.1881, 2.4789, -8.5592, 5.0088).finished();
  EXPECT_LT((delta - expected).cwiseAbs().maxCoeff(), 2e-3);
  EXPECT_FALSE(r.unilateral_ok);  // P_ly < 0: not a valid double impact
  // The energy lost does not depend on the null-space part of dtheta^- (6.401 J).
  EXPECT_NEAR(dynamics::kineticEnergy<double>(model_, theta_, dtheta_) -
                  dynamics::kineticEnergy<double>(model_, theta_, r.dtheta_plus),
              22.889 - 16.489, 2e-3);
}

TEST_F(MuReferenceImpact, SingleImpactImpulsesAndClassification) {
  const auto r = dynamics::singleImpact(model_, theta_, dtheta_);
  EXPECT_NEAR(r.trailing_velocity(0), 0.0650, 2e-3);
  EXPECT_NEAR(r.trailing_velocity(1), 0.2500, 2e-3);
  EXPECT_NEAR(r.impulse_leading(0), -1.3560, 2e-3);
  EXPECT_NEAR(r.impulse_leading(1), 11.7933, 2e-3);
  const VecD delta = r.dtheta_plus - dtheta_;
  const VecD expected = (VecD(5) << 0.4583, -2.7698, 2.1488, -7.4609, 4.3766).finished();
  EXPECT_LT((delta - expected).cwiseAbs().maxCoeff(), 2e-3);
  EXPECT_TRUE(r.unilateral_ok);
  EXPECT_TRUE(r.friction_ok);  // mu_S = -0.115
  EXPECT_NEAR(
      dynamics::kineticEnergy<double>(model_, theta_, dtheta_) -
          dynamics::kineticEnergy<double>(model_, theta_, r.dtheta_plus, r.trailing_velocity),
      22.889 - 16.993, 2e-3);
  EXPECT_EQ(dynamics::classifyImpact(model_, theta_, dtheta_), dynamics::ImpactType::kSingle);
}

}  // namespace
}  // namespace gaitopt::test
