// The pre-impact state of Mu (2004) sec. 5.3 and one point of the contact-event study: geometry
// to rounding, the reference cases of docs/derivations.md#impact-reference-values, and the refined
// criterion against sign conditions recomputed from the independent floating-base impulse problem.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "dynamics/kinematics.hpp"
#include "gaits/impact/impact_point.hpp"
#include "gaits/impact/impact_posture.hpp"
#include "support/fixtures.hpp"
#include "support/floating_base.hpp"

namespace gaitopt::test {
namespace {

using dynamics::ImpactType;
using gaits::ImpactPostureParams;

class ImpactPostureTest : public ::testing::Test {
 protected:
  dynamics::Model model_ = loadNamed("mu2004_five_link");
  std::mt19937 rng_{7};

  /// A random reachable point: step 0.05..0.95 m, sigma 1..60 deg, alpha 3..177 deg.
  ImpactPostureParams randomParams() {
    const VecD r = randomVec(rng_, 4, 0, 1);
    return {0.05 + 0.9 * r(0), (1 + 59 * r(1)) * kDeg, (3 + 174 * r(2)) * kDeg, 0.2 + 2 * r(3)};
  }
};

TEST_F(ImpactPostureTest, SwingTipLandsAtTheStepWithTheRequestedVelocity) {
  for (int trial = 0; trial < 200; ++trial) {
    const ImpactPostureParams p = randomParams();
    const auto s = gaits::impactPosture(model_, p);
    const Vec2d tip = dynamics::swingTip(model_, s.theta);
    EXPECT_NEAR(tip(0), p.step_length, 1e-12);
    EXPECT_NEAR(tip(1), 0.0, 1e-12);
    // Sec. 5.3 conditions: x_h = S_L / 4 (= step_length / 2), theta3 = 0, sigma = theta1 - theta2.
    EXPECT_NEAR(dynamics::hip(model_, s.theta)(0), p.step_length / 2, 1e-12);
    EXPECT_NEAR(dynamics::hip(model_, s.theta)(1), gaits::impactHipHeight(model_, p), 1e-12);
    EXPECT_EQ(s.theta(2), 0.0);
    EXPECT_NEAR(s.theta(0) - s.theta(1), p.knee_bias, 1e-12);
    // Xdot_e^- = -V_e (cos alpha, sin alpha): downward, at alpha from the -x axis (sec. 5.2.1).
    const Vec2d v = dynamics::pointJacobian(model_.tipWeights(), s.theta) * s.dtheta;
    EXPECT_NEAR(v(0), -p.approach_speed * std::cos(p.approach_angle), 1e-12);
    EXPECT_NEAR(v(1), -p.approach_speed * std::sin(p.approach_angle), 1e-12);
    EXPECT_NEAR(std::atan2(-v(1), -v(0)), p.approach_angle, 1e-12);
  }
}

TEST_F(ImpactPostureTest, ReproducesMuReferencePosture) {
  // S_L 0.7 m, sigma 15 deg -> theta in degrees, hip (0.175, 0.60374) m
  // (docs/derivations.md#impact-reference-values).
  const auto s = gaits::impactPosture(model_, {0.35, 15 * kDeg, 90 * kDeg, 1.0});
  const VecD expected = (VecD(5) << 23.3079, 8.3079, 0, 155.9782, 170.9782).finished();
  EXPECT_LT((s.theta / kDeg - expected).cwiseAbs().maxCoeff(), 1e-4);
  EXPECT_NEAR(dynamics::hip(model_, s.theta)(1), 0.60374, 1e-5);
}

TEST_F(ImpactPostureTest, MuReferenceCaseIsASingleImpact) {
  // P_l = (-1.6583, -3.6015) (P_ly < 0), ydot_b+ = 0.25 > 0, mu_S = -0.115
  // (docs/derivations.md#impact-reference-values).
  const auto pt = gaits::evaluateImpactPoint(model_, {0.35, 15 * kDeg, 90 * kDeg, 1.0});
  EXPECT_EQ(pt.type, ImpactType::kSingle);
  EXPECT_NEAR(pt.double_model.impulse_trailing(0), -1.6583, 2e-3);
  EXPECT_NEAR(pt.double_model.impulse_trailing(1), -3.6015, 2e-3);
  EXPECT_NEAR(pt.single_model.trailing_velocity(1), 0.2500, 2e-3);
  EXPECT_NEAR(pt.mu_s, -1.3560 / 11.7933, 2e-3);
}

TEST_F(ImpactPostureTest, MuLongStepCaseIsADoubleImpact) {
  // S_L 1.8 m, sigma 10 deg, alpha 100 deg -> P_l = (2.8726, 2.1938), P_r = (-6.9136, 8.9482),
  // ydot_b+ = -0.0628 (docs/derivations.md#impact-reference-values).
  const auto pt = gaits::evaluateImpactPoint(model_, {0.9, 10 * kDeg, 100 * kDeg, 1.0});
  EXPECT_EQ(pt.type, ImpactType::kDouble);
  EXPECT_NEAR(pt.double_model.impulse_trailing(0), 2.8726, 2e-3);
  EXPECT_NEAR(pt.double_model.impulse_trailing(1), 2.1938, 2e-3);
  EXPECT_NEAR(pt.double_model.impulse_leading(0), -6.9136, 2e-3);
  EXPECT_NEAR(pt.double_model.impulse_leading(1), 8.9482, 2e-3);
  EXPECT_NEAR(pt.single_model.trailing_velocity(1), -0.0628, 2e-3);
  EXPECT_NEAR(pt.mu_l, 2.8726 / 2.1938, 2e-3);
  EXPECT_NEAR(pt.mu_r, -6.9136 / 8.9482, 2e-3);
}

TEST_F(ImpactPostureTest, TypeAgreesWithSignsFromTheFloatingBaseImpulseProblem) {
  // Refined criterion (sec. 5.3): double needs P_ly > 0, single needs ydot_b+ > 0. Both signs are
  // recomputed here from the 7-DOF KKT solve, not from Mu's closed forms.
  const int n = model_.nLinks();
  int seen[4] = {0, 0, 0, 0};
  for (int trial = 0; trial < 400; ++trial) {
    const ImpactPostureParams p = randomParams();
    const auto s = gaits::impactPosture(model_, p);
    const FloatingBase fb = floatingBase(model_, s.theta, s.dtheta);
    Eigen::VectorXd qdot = Eigen::VectorXd::Zero(n + 2);
    qdot.tail(n) = s.dtheta;  // B at rest before impact
    Eigen::MatrixXd both(4, n + 2);
    both << fb.jac_b, fb.jac_e;
    const double p_ly = solveKkt(fb.mass, fb.mass * qdot, both, Eigen::VectorXd::Zero(4)).second(1);
    const double ydot_b =
        solveKkt(fb.mass, fb.mass * qdot, fb.jac_e, Eigen::VectorXd::Zero(2)).first(1);
    const ImpactType expected = p_ly > 0
                                    ? (ydot_b > 0 ? ImpactType::kEither : ImpactType::kDouble)
                                    : (ydot_b > 0 ? ImpactType::kSingle : ImpactType::kNeither);
    const auto pt = gaits::evaluateImpactPoint(model_, p);
    EXPECT_EQ(pt.type, expected) << "step " << p.step_length << " sigma " << p.knee_bias / kDeg
                                 << " alpha " << p.approach_angle / kDeg;
    ++seen[static_cast<int>(pt.type)];
  }
  // The random draw reaches all four regions of Mu's Fig. 5.2.
  for (int count : seen) EXPECT_GT(count, 0);
}

TEST_F(ImpactPostureTest, TypeAndRatiosDoNotDependOnTheApproachSpeed) {
  // Sec. 5.2 remark 2: impulses are linear in V_e, so (5.3) and (5.5) depend on alpha only.
  for (int trial = 0; trial < 50; ++trial) {
    ImpactPostureParams p = randomParams();
    const auto slow = gaits::evaluateImpactPoint(model_, p);
    p.approach_speed *= 3;
    const auto fast = gaits::evaluateImpactPoint(model_, p);
    EXPECT_EQ(slow.type, fast.type);
    EXPECT_NEAR(slow.mu_l, fast.mu_l, 1e-9 * (1 + std::abs(slow.mu_l)));
    EXPECT_NEAR(slow.mu_s, fast.mu_s, 1e-9 * (1 + std::abs(slow.mu_s)));
    EXPECT_LT((3 * slow.single_model.impulse_leading - fast.single_model.impulse_leading).norm(),
              1e-9);
  }
}

TEST_F(ImpactPostureTest, RejectsSingularAndUnreachablePostures) {
  EXPECT_THROW(gaits::impactPosture(model_, {0.35, 0.0, 90 * kDeg, 1}), std::invalid_argument);
  EXPECT_THROW(gaits::impactPosture(model_, {0.35, 15 * kDeg, 0.0, 1}), std::invalid_argument);
  EXPECT_THROW(gaits::impactPosture(model_, {0.35, 15 * kDeg, std::numbers::pi, 1}),
               std::invalid_argument);
  EXPECT_THROW(gaits::impactPosture(model_, {0.35, 15 * kDeg, 90 * kDeg, 0}),
               std::invalid_argument);
  const double too_long = gaits::maxImpactStepLength(model_, 15 * kDeg);
  EXPECT_THROW(gaits::impactPosture(model_, {too_long, 15 * kDeg, 90 * kDeg, 1}),
               std::domain_error);
  EXPECT_THROW(gaits::impactPosture(loadNamed("compass_gait"), {0.35, 15 * kDeg, 90 * kDeg, 1}),
               std::invalid_argument);
}

}  // namespace
}  // namespace gaitopt::test
