// Gait metrics on synthetic trajectories whose answers are known in closed form.
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <stdexcept>
#include <utility>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/LU>

#include "dynamics/floating_base.hpp"
#include "dynamics/impact/impact.hpp"
#include "dynamics/joint_coordinates.hpp"
#include "dynamics/kinematics.hpp"
#include "gaits/export/metrics.hpp"
#include "support/fixtures.hpp"
#include "support/floating_base.hpp"

namespace gaitopt::test {
namespace {

using gaits::Knot;
using gaits::Phase;
using gaits::Trajectory;

Knot restKnot(double t, Phase phase, int n = 5) {
  Knot k;
  k.t = t;
  k.phase = phase;
  k.theta = k.dtheta = k.ddtheta = k.tau = Eigen::VectorXd::Zero(n);
  return k;
}

/// Knot times of a step: SSP on [0, 0.6] every 0.1 s, the switch pair, DSP to 0.7.
std::vector<std::pair<double, Phase>> stepTimes() {
  std::vector<std::pair<double, Phase>> times;
  for (int i = 0; i <= 6; ++i) times.emplace_back(0.1 * i, Phase::kSsp);
  times.emplace_back(0.1 * 6, Phase::kDsp);
  times.emplace_back(0.7, Phase::kDsp);
  return times;
}

/// A trajectory whose knots are `knot` with only time and phase changed.
Trajectory constantStep(const Knot& knot, double step_length = 0.35) {
  std::vector<Knot> knots;
  for (const auto& [t, phase] : stepTimes()) {
    Knot k = knot;
    k.t = t;
    k.phase = phase;
    knots.push_back(k);
  }
  return Trajectory("test", step_length, knots);
}

/// Force at B for an SSP knot whose ZMP is at x: M_B = -tau0 = x F_y.
Knot withZmp(Knot k, double x, double fy = 200) {
  k.force_stance = Eigen::Vector2d(0, fy);
  k.tau(0) = -x * fy;
  return k;
}

// --- energy ----------------------------------------------------------------------------------

TEST(GaitMetrics, AbsoluteWorkOfConstantTorqueAndRateIsExact) {
  const Eigen::VectorXd dq = (Eigen::VectorXd(5) << 0.5, -1.2, 2.0, 0.3, -0.7).finished();
  Knot k = restKnot(0, Phase::kSsp);
  k.dtheta = dynamics::toAbsolute(VecD(dq));
  k.tau = (Eigen::VectorXd(5) << 10, 20, -5, 7, -3).finished();  // mixed signs: |.| per joint
  const Trajectory traj = constantStep(k);
  const double expected = (k.tau.array() * dq.array()).abs().sum() * 0.7;  // = 38.29 * 0.7
  EXPECT_NEAR(gaits::absoluteWork(traj), expected, 1e-13 * expected);
  const auto model = loadNamed("mu2004_five_link");
  EXPECT_NEAR(gaits::costOfTransport(traj, model),
              expected / (model.totalMass() * model.gravity() * 0.35), 1e-13);
  EXPECT_THROW(gaits::costOfTransport(constantStep(k, 0.0), model), std::invalid_argument);
}

TEST(GaitMetrics, TorqueSquaredOfLinearTorqueMatchesClosedForm) {
  const Eigen::VectorXd a = (Eigen::VectorXd(3) << 4, -7, 1.5).finished();
  const double duration = 0.7;
  const int intervals = 1000;
  std::vector<Knot> knots;
  for (int i = 0; i <= intervals; ++i) {
    Knot k = restKnot(duration * i / intervals, Phase::kSsp, 3);
    k.tau = a * k.t;
    knots.push_back(k);
  }
  const Trajectory traj("test", 0.35, knots);
  // Integral of sum_j (a_j t)^2 over [0, T]; the trapezoid rule is O(h^2) off (5e-7 relative).
  const double expected = a.squaredNorm() * std::pow(duration, 3) / 3;
  EXPECT_NEAR(gaits::torqueSquaredIntegral(traj), expected, 1e-6 * expected);
}

TEST(GaitMetrics, PeakTorquePerJoint) {
  std::vector<Knot> knots;
  const std::vector<Eigen::Vector3d> taus{{1, -2, 0}, {-5, 1, 0.5}, {3, 4, -0.25}};
  for (size_t i = 0; i < taus.size(); ++i) {
    Knot k = restKnot(0.1 * static_cast<double>(i), Phase::kSsp, 3);
    k.tau = taus[i];
    knots.push_back(k);
  }
  EXPECT_EQ(gaits::peakTorque(Trajectory("test", 0.3, knots)), Eigen::Vector3d(5, 4, 0.5));
}

// --- contact forces --------------------------------------------------------------------------

/// SSP knots carry a bogus force at E (E is in the air there); DSP knots a real one.
Trajectory contactStep() {
  std::vector<Knot> knots;
  for (const auto& [t, phase] : stepTimes()) {
    Knot k = restKnot(t, phase);
    if (phase == Phase::kSsp) {
      k.force_stance = Eigen::Vector2d(30, 300 - 100 * t);  // ratio 0.1 .. 0.125
      k.force_swing = Eigen::Vector2d(100, -40);            // must be ignored
    } else {
      k.force_stance = Eigen::Vector2d(12, 120);                 // ratio 0.1
      k.force_swing = Eigen::Vector2d(-24, t < 0.65 ? 80 : 60);  // ratio 0.3, then 0.4
    }
    knots.push_back(k);
  }
  return Trajectory("test", 0.35, knots);
}

TEST(GaitMetrics, PostureIsTheLargestTorsoLeanAndKneeFlexionOfEitherLeg) {
  const dynamics::Model model = loadNamed("mu2004_five_link");  // links: 0, 1 stance, 2 torso
  Knot bent = restKnot(0, Phase::kSsp);
  bent.theta << 0.1, 0.5, -0.3, 0.2, -0.7;  // stance knee 0.4, swing knee 0.9, torso 0.3
  Knot straight = restKnot(0, Phase::kSsp);
  straight.theta << 0.2, 0.2, 0.1, -0.4, -0.4;
  std::vector<Knot> knots{straight, bent, straight};
  for (size_t i = 0; i < knots.size(); ++i) knots[i].t = 0.1 * static_cast<double>(i);
  const gaits::Posture p = gaits::posture(Trajectory("test", 0.35, knots), model);
  EXPECT_DOUBLE_EQ(p.torso_lean, 0.3);
  EXPECT_DOUBLE_EQ(p.stance_knee, 0.4);
  EXPECT_DOUBLE_EQ(p.swing_knee, 0.9);
  // A robot without knees or torso has none to bend.
  const gaits::Posture compass =
      gaits::posture(constantStep(restKnot(0, Phase::kSsp, 2)), loadNamed("compass_gait"));
  EXPECT_EQ(compass.torso_lean + compass.stance_knee + compass.swing_knee, 0.0);
}

TEST(GaitMetrics, MinNormalForceUsesOnlyTipsInContact) {
  EXPECT_EQ(gaits::minNormalForce(contactStep()), 60);  // E in the DSP, not -40 from the SSP
  auto knots = contactStep().knots();
  knots.resize(7);  // SSP only: B alone, lowest at t = 0.6
  EXPECT_NEAR(gaits::minNormalForce(Trajectory("test", 0.35, knots)), 240, 1e-12);
}

TEST(GaitMetrics, MaxFrictionRatioUsesOnlyTipsInContact) {
  EXPECT_DOUBLE_EQ(gaits::maxFrictionRatio(contactStep()), 24.0 / 60);
  auto knots = contactStep().knots();
  knots.resize(7);
  EXPECT_DOUBLE_EQ(gaits::maxFrictionRatio(Trajectory("test", 0.35, knots)), 30.0 / 240);
  knots[3].force_stance.y() = 0;  // B touching without load: no finite friction suffices
  // The ratio itself is infinite (IEEE), not a bound: ocp::kInf (1e20) would be a wrong answer.
  EXPECT_EQ(gaits::maxFrictionRatio(Trajectory("test", 0.35, knots)),
            std::numeric_limits<double>::infinity());
}

// --- ZMP -------------------------------------------------------------------------------------

TEST(GaitMetrics, ZmpOfAPureVerticalForceIsAtTheTipShiftedByTheAnkleTorque) {
  Knot k = restKnot(0, Phase::kSsp);
  k.force_stance = Eigen::Vector2d(0, 230);
  k.force_swing = Eigen::Vector2d(0, 500);  // SSP: ignored
  EXPECT_EQ(gaits::zmpX(k, 0.35), 0.0);
  k.tau(0) = -230 * 0.05;  // ground moment -tau0 > 0 (ccw) moves the ZMP forward
  EXPECT_NEAR(gaits::zmpX(k, 0.35), 0.05, 1e-15);
  // DSP: E at the step length shares the load 1:3.
  Knot d = restKnot(0, Phase::kDsp);
  d.force_stance = Eigen::Vector2d(5, 100);
  d.force_swing = Eigen::Vector2d(-5, 300);
  EXPECT_NEAR(gaits::zmpX(d, 0.4), 0.3, 1e-15);
}

TEST(GaitMetrics, ZmpMarginUsesTheFootInSspAndBothTipsInDsp) {
  const auto model = loadNamed("mu2004_five_link");  // heel 0.05, toe 0.15
  ASSERT_EQ(model.foot().heel, 0.05);
  ASSERT_EQ(model.foot().toe, 0.15);
  std::vector<Knot> ssp{withZmp(restKnot(0, Phase::kSsp), 0.1),
                        withZmp(restKnot(0.1, Phase::kSsp), -0.02)};
  EXPECT_NEAR(gaits::minZmpMargin(Trajectory("test", 0.8, ssp), model), 0.03, 1e-15);
  ssp[1] = withZmp(ssp[1], -0.08);  // behind the heel: outside, negative
  EXPECT_NEAR(gaits::minZmpMargin(Trajectory("test", 0.8, ssp), model), -0.03, 1e-15);

  // DSP with equal loads: ZMP at L/2 = 0.4, far outside the SSP foot [-0.05, 0.15] but inside
  // [-heel, L + toe] = [-0.05, 0.95].
  std::vector<Knot> dsp;
  for (double t : {0.0, 0.1}) {
    Knot k = restKnot(t, Phase::kDsp);
    k.force_stance = k.force_swing = Eigen::Vector2d(0, 100);
    dsp.push_back(k);
  }
  EXPECT_NEAR(gaits::minZmpMargin(Trajectory("test", 0.8, dsp), model), 0.45, 1e-15);
}

// --- touchdown -------------------------------------------------------------------------------

class Touchdown : public ::testing::Test {
 protected:
  /// Stance leg leaning forward, swing leg mirrored so that E is on the ground.
  VecD theta() const {
    VecD th(5);
    th << 0.3, 0.3, 0.1, std::numbers::pi - 0.3, std::numbers::pi - 0.3;
    return th;
  }
  /// dtheta with the component that moves the swing tip removed: the null space of J (2.23c).
  VecD softLanding(const VecD& dtheta) const {
    const Eigen::MatrixXd jac = dynamics::pointJacobian(model_.tipWeights(), theta());
    const Eigen::MatrixXd proj =
        Eigen::MatrixXd::Identity(5, 5) - jac.transpose() * (jac * jac.transpose()).inverse() * jac;
    return proj * dtheta;
  }
  Trajectory step(const VecD& dtheta_minus) const {
    std::vector<Knot> knots{restKnot(0, Phase::kSsp), restKnot(0.5, Phase::kSsp),
                            restKnot(0.5, Phase::kDsp), restKnot(0.6, Phase::kDsp)};
    for (Knot& k : knots) k.theta = theta();
    knots[1].dtheta = dtheta_minus;                                         // the pre-impact state
    knots[0].dtheta = knots[2].dtheta = Eigen::VectorXd::Constant(5, 9.0);  // decoys
    return Trajectory(model_.name(), 0.35, knots);
  }

  dynamics::Model model_ = loadNamed("mu2004_five_link");
  std::mt19937 rng_{7};
};

TEST_F(Touchdown, PostureHasTheSwingTipOnTheGround) {
  EXPECT_NEAR(dynamics::swingTip(model_, theta())(1), 0, 1e-12);
}

TEST_F(Touchdown, NoJumpWhenTheSwingTipArrivesAtRest) {
  const VecD dtheta = softLanding(randomVec(rng_, 5, -2, 2));
  ASSERT_LT((dynamics::pointJacobian(model_.tipWeights(), theta()) * dtheta).norm(), 1e-12);
  ASSERT_GT(dtheta.norm(), 0.5);  // the robot still moves; only the tip is at rest
  EXPECT_LT(gaits::touchdownVelocityJump(step(dtheta), model_), 1e-10);
  EXPECT_LT(std::abs(gaits::impactEnergyLoss(step(dtheta), model_)), 1e-10);
}

/// The double impact from the impulse balance of the free chain, q = (x_b, y_b, theta), not
/// from Mu's reduced form (2.25-2.28): D_ext (qdot+ - qdot-) = J_B^T P_B + J_E^T P_E with both
/// tips at rest after, J_B qdot+ = J_E qdot+ = 0 (Mu 2.50, 2.57). Returns qdot+ and (P_B, P_E).
std::pair<Eigen::VectorXd, Eigen::VectorXd> impulsesThatStopBothTips(const dynamics::Model& m,
                                                                     const VecD& theta,
                                                                     const Eigen::VectorXd& qdot) {
  const int nq = m.nLinks() + 2;
  Eigen::MatrixXd jac(4, nq);
  jac << Eigen::MatrixXd::Identity(2, nq),
      dynamics::floatingJacobian<double>(m.tipWeights(), theta);
  const Eigen::MatrixXd d = dynamics::floatingBaseMassMatrix<double>(m, theta);
  return solveKkt(d, d * qdot, jac, Eigen::VectorXd::Zero(4));
}

TEST_F(Touchdown, JumpAndLossFollowFromTheImpulsesThatStopBothTips) {
  const VecD dtheta = randomVec(rng_, 5, -2, 2);
  Eigen::VectorXd before = Eigen::VectorXd::Zero(7);  // B at rest before the strike
  before.tail(5) = dtheta;
  const auto [after, impulses] = impulsesThatStopBothTips(model_, theta(), before);
  ASSERT_LT(after.head<2>().norm(), 1e-12);  // B stays
  const double jump = (after.tail(5) - dtheta).norm();
  // Kelvin's theorem for an impulsive impact: K+ - K- = sum_tips P . (v- + v+) / 2. Both tips
  // end at rest and B was, so the loss is -P_E . v_E- / 2.
  const Vec2d v_e = dynamics::pointVelocity<double>(model_.tipWeights(), theta(), dtheta);
  const double loss = -0.5 * impulses.tail<2>().dot(v_e);
  EXPECT_GT(jump, 0.1);
  EXPECT_GT(loss, 0.0);  // a plastic impact only dissipates
  // Two different solves agree to rounding: measured 3e-13 (jump) and 2e-14 (loss) relative.
  EXPECT_NEAR(gaits::touchdownVelocityJump(step(dtheta), model_), jump, 1e-10 * jump);
  EXPECT_NEAR(gaits::impactEnergyLoss(step(dtheta), model_), loss, 1e-10 * loss);
}

TEST_F(Touchdown, AStepWithoutADoubleSupportPhaseEndsInTheSingleImpact) {
  const VecD dtheta = randomVec(rng_, 5, -2, 2);
  auto knots = step(dtheta).knots();
  knots.resize(2);  // the SSP ends at the strike (knot 1), no DSP follows
  const Trajectory ssp_only(model_.name(), 0.35, knots);
  const auto impact = dynamics::singleImpact(model_, theta(), dtheta);
  // Energy from the floating-base mass matrix, q = (x_b, y_b, theta): B at rest before, moving
  // with Xdot_b^+ (Mu 2.36b) after.
  const Eigen::MatrixXd d = dynamics::floatingBaseMassMatrix<double>(model_, theta());
  Eigen::VectorXd before = Eigen::VectorXd::Zero(7), after = before;
  before.tail(5) = dtheta;
  after << impact.trailing_velocity, impact.dtheta_plus;
  const double loss = 0.5 * before.dot(d * before) - 0.5 * after.dot(d * after);
  EXPECT_GT(loss, 0.0);
  EXPECT_GT(impact.trailing_velocity.norm(), 1e-3);  // B moves: its energy counts
  EXPECT_NEAR(gaits::impactEnergyLoss(ssp_only, model_), loss, 1e-10 * (1 + loss));
  EXPECT_NEAR(gaits::touchdownVelocityJump(ssp_only, model_), (impact.dtheta_plus - dtheta).norm(),
              1e-12);
}

TEST_F(Touchdown, NoTouchdownWhenTheStepEndsInTheDoubleSupport) {
  auto knots = step(randomVec(rng_, 5, -2, 2)).knots();
  knots.erase(knots.begin(), knots.begin() + 2);  // a DSP alone
  const Trajectory dsp_only(model_.name(), 0.35, knots);
  EXPECT_EQ(gaits::touchdownVelocityJump(dsp_only, model_), 0.0);
  EXPECT_EQ(gaits::impactEnergyLoss(dsp_only, model_), 0.0);
}

}  // namespace
}  // namespace gaitopt::test
