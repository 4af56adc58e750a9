// HZD on RABBIT (sim/controllers/hzd_*.hpp) walking Kelly's torque-squared optimum
// (configs/ocp/rabbit_kelly2017.yaml, solved once here in about 0.1 s): the Bezier fit of the
// actuated joints, the impact invariance of the zero dynamics manifold, the exact output decay
// of the feedback-linearised loop, and the restricted Poincare map measured on the closed loop
// against the zero-dynamics integral (Westervelt, Grizzle, Koditschek 2003, Theorem 3).
#include <gtest/gtest.h>

#include <cmath>

#include "dynamics/kinematics.hpp"
#include "dynamics/robot_files/robot_config.hpp"
#include "ocp/guess/initial_guess.hpp"
#include "ocp/problem/gait_problem.hpp"
#include "ocp/solve/ipopt_adapter.hpp"
#include "sim/controllers/hzd_controller.hpp"
#include "sim/scenario/scenario.hpp"
#include "sim/studies/hzd_poincare.hpp"
#include "sim/studies/poincare.hpp"
#include "sim/walk/hybrid_walk.hpp"

namespace gaitopt::sim {
namespace {

class RabbitHzd : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    const auto config =
        ocp::loadOcpConfig(std::string(GAITOPT_SOURCE_DIR) + "/configs/ocp/rabbit_kelly2017.yaml");
    model_ = new dynamics::Model(dynamics::loadRobot(config.robot_path));
    const ocp::GaitProblem p =
        ocp::buildGaitProblem(*model_, config, ocp::polynomialGuess(*model_, config));
    const ocp::SolveResult r = ocp::solveWithIpopt(p.nlp, config.solver);
    ASSERT_EQ(r.status, "Solve_Succeeded");
    gait_ = new gaits::Trajectory(ocp::reconstructDense(p, *model_, r.x, 1000));
    ref_ = new Reference(*gait_);
    controller_ =
        makeHzdController(*model_, *ref_, std::make_unique<PdLaw>(TrackingGains{})).release();
  }
  static void TearDownTestSuite() {
    delete controller_;
    delete ref_;
    delete gait_;
    delete model_;
  }
  static const VirtualConstraints& vc() { return controller_->constraints(); }

  static dynamics::Model* model_;
  static gaits::Trajectory* gait_;
  static Reference* ref_;
  static HzdController* controller_;
};
dynamics::Model* RabbitHzd::model_ = nullptr;
gaits::Trajectory* RabbitHzd::gait_ = nullptr;
Reference* RabbitHzd::ref_ = nullptr;
HzdController* RabbitHzd::controller_ = nullptr;

// The 40-node spline reproduces the four actuated joints of the 25-segment optimum within
// 1e-3 rad at every exported sample (1 kHz), and their rates along the gait within 0.01 rad/s.
TEST_F(RabbitHzd, FitReproducesTheActuatedJoints) {
  EXPECT_LT(vc().fitError(), 1e-3);
  for (const gaits::Knot& k : gait_->knots()) {
    EXPECT_LT(vc().output(k.theta).cwiseAbs().maxCoeff(), 1e-3) << k.t;
    EXPECT_LT(vc().outputRate(k.theta, k.dtheta).cwiseAbs().maxCoeff(), 1e-2) << k.t;
  }
}

// The spline's derivatives against central differences of h_d, inside and beyond the step.
TEST_F(RabbitHzd, DerivativesMatchFiniteDifferences) {
  const double step = 1e-5;
  for (double s : {0.1, 0.5, 0.9, 1.05}) {
    const double phi = vc().phaseStart() + s * (vc().phaseEnd() - vc().phaseStart());
    const auto lo = vc().at(phi - step), mid = vc().at(phi), hi = vc().at(phi + step);
    EXPECT_LT((mid.dh - (hi.h - lo.h) / (2 * step)).norm(), 1e-6);
    EXPECT_LT((mid.ddh - (hi.dh - lo.dh) / (2 * step)).norm(), 1e-5);
  }
}

// Z is invariant under impact: the posture at phi- touches the ground, and the relabelled
// impact of any motion along Z lands on Z again (y = 0 and ydot = 0).
TEST_F(RabbitHzd, ImpactMapsTheZeroDynamicsManifoldIntoItself) {
  const VecD theta = vc().posture(vc().phaseEnd());
  EXPECT_NEAR(dynamics::swingTip<double>(*model_, theta)(1), 0.0, 1e-9);
  EXPECT_NEAR(dynamics::swingTip<double>(*model_, theta)(0), gait_->stepLength(), 1e-6);
  const ImpactImage image =
      hzdImpact(*model_, theta, 1.3 * vc().tangent(vc().phaseEnd()), vc().singleImpact());
  EXPECT_LT(vc().output(image.theta).norm(), 1e-9);
  EXPECT_LT(vc().outputRate(image.theta, image.dtheta).norm(), 1e-9);
}

// With the plant equal to the controller's model and no torque clipping, yddot = v exactly:
// a 0.02 rad error on one output follows y0 (1 + w t) exp(-w t) (PD 400, 40: w = 20 rad/s,
// critically damped) while the other outputs stay at zero.
TEST_F(RabbitHzd, OutputDecaysAsTheLinearisedLoop) {
  const double phi = vc().phaseStart();
  VecD theta = vc().posture(phi);
  theta.tail(2).array() -= 0.02;  // the swing leg turned back: only q_3 = theta_2 - theta_3 moves
  const VecD dtheta = vc().tangent(phi) * 1.0;
  const double y0 = vc().output(theta)(2);
  ASSERT_NEAR(y0, 0.02, 1e-12);
  double worst = 0;
  int samples = 0;
  const WalkLog log = [&](const WalkSample& s) {
    if (s.step != 0 || s.t > 0.3) return;
    const VecD y = vc().output(s.theta);
    const double expected = y0 * (1 + 20 * s.t) * std::exp(-20 * s.t);
    worst = std::max(worst,
                     std::abs(y(2) - expected) + std::abs(y(0)) + std::abs(y(1)) + std::abs(y(3)));
    ++samples;
  };
  simulateStep(*model_, *controller_, *ref_, theta, dtheta, {}, log);
  EXPECT_GT(samples, 100);
  EXPECT_LT(worst, 1e-6);
}

// The restricted map measured on the closed loop (states started on Z, one step simulated)
// against the zero-dynamics integral: same multiplier delta^2 and the same fixed point.
TEST_F(RabbitHzd, MeasuredRestrictedMultiplierMatchesTheAnalyticOne) {
  const RestrictedMap a = restrictedMap(*model_, vc());
  ASSERT_TRUE(a.walks);
  const MeasuredRestrictedMap m =
      measureRestrictedMap(*model_, *controller_, *ref_, vc(), a.multiplier * a.zeta_minus);
  ASSERT_TRUE(m.ok) << m.failure;
  EXPECT_NEAR(m.multiplier, a.multiplier, 1e-4);
  EXPECT_NEAR(m.zeta_plus, a.multiplier * a.zeta_minus, 1e-4 * a.zeta_minus);
}

// Three steps from the analytic fixed point stay on it: the same angular momentum after every
// impact, the outputs at zero (to 1e-4 rad: touchdown is detected 1e-6 m above the ground,
// a hair before phi-), and each step the gait's length.
TEST_F(RabbitHzd, StepsFromTheFixedPointStayOnTheOrbit) {
  const RestrictedMap a = restrictedMap(*model_, vc());
  const double phi = vc().phaseStart(), zeta_plus = a.multiplier * a.zeta_minus;
  VecD theta = vc().posture(phi), along = vc().tangent(phi);
  VecD dtheta = along * std::sqrt(2 * zeta_plus) / stanceAngularMomentum(*model_, theta, along);
  for (int k = 0; k < 3; ++k) {
    const StepResult s = simulateStep(*model_, *controller_, *ref_, theta, dtheta, {});
    ASSERT_TRUE(s.ok) << s.failure;
    EXPECT_EQ(s.impact, vc().singleImpact() ? "single" : "double");
    EXPECT_NEAR(s.advance, gait_->stepLength(), 1e-4);
    const double sigma = stanceAngularMomentum(*model_, s.theta, s.dtheta);
    EXPECT_NEAR(sigma * sigma / 2, zeta_plus, 1e-4 * zeta_plus);
    EXPECT_LT(vc().output(s.theta).norm(), 1e-4);
    theta = s.theta;
    dtheta = s.dtheta;
  }
}

// Started on Z 30 % above the fixed point's zeta+, the walk returns to it geometrically: each
// step multiplies the distance by delta^2 (the restricted map is affine in zeta).
TEST_F(RabbitHzd, ZeroDynamicsReturnToTheFixedPointByTheMultiplier) {
  const RestrictedMap a = restrictedMap(*model_, vc());
  const double fixed = a.multiplier * a.zeta_minus;
  double zeta = 1.3 * fixed;
  for (int k = 0; k < 3; ++k) {
    const double next = restrictedReturn(*model_, *controller_, *ref_, vc(), zeta);
    ASSERT_TRUE(std::isfinite(next)) << "step " << k;
    EXPECT_NEAR((next - fixed) / (zeta - fixed), a.multiplier, 1e-3) << "step " << k;
    zeta = next;
  }
}

// `gaitopt simulate --controller hzd` on Kelly's gait: 20 steps from the gait's own start (on Z
// up to the OCP's tolerance), at the gait's step length and speed, and the full-state Poincare
// map's largest multiplier equal to the restricted one (the outputs' own multipliers, e^-20T,
// are negligible). About 3 s: optimised builds only.
TEST_F(RabbitHzd, WalksTwentyStepsThroughTheScenario) {
#ifndef NDEBUG
  GTEST_SKIP() << "20 steps and two Poincare maps: optimised builds only";
#endif
  Scenario scenario;
  scenario.controller = "hzd";
  scenario.poincare = true;
  const ScenarioResult r = runScenario(*model_, *ref_, scenario);
  EXPECT_EQ(r.walk.steps_completed, 20) << r.walk.failure;
  const WalkTotals totals = completedTotals(r.walk);
  EXPECT_NEAR(totals.distance / 20, gait_->stepLength(), 1e-4);
  EXPECT_NEAR(totals.duration / 20, gait_->duration(), 1e-3);
  ASSERT_TRUE(r.poincare && r.poincare->ok) << (r.poincare ? r.poincare->failure : "");
  ASSERT_TRUE(r.hzd_map && r.hzd_measured && r.hzd_measured->ok);
  EXPECT_NEAR(r.poincare->max_multiplier, r.hzd_map->multiplier, 0.01);
  EXPECT_NEAR(r.hzd_measured->multiplier, r.hzd_map->multiplier, 1e-3);
}

// Kelly's gait strikes at speed: with restitution the landing tip leaves the ground, which the
// pinned phases after the impact cannot walk (a walk of 20 steps, 2.09 s each, was reported with
// e = 0.5). The walk ends at the first touchdown and says why.
TEST_F(RabbitHzd, AReboundOfTheLandingTipEndsTheWalk) {
  Scenario scenario;
  scenario.controller = "hzd";
  scenario.steps = 3;
  scenario.rules.restitution = 0.5;
  const ScenarioResult r = runScenario(*model_, *ref_, scenario);
  EXPECT_EQ(r.walk.steps_completed, 0);
  EXPECT_TRUE(r.walk.fell);
  EXPECT_NE(r.walk.failure.find("the landing tip rebounds at"), std::string::npos)
      << r.walk.failure;
  scenario.rules.restitution = 0;
  EXPECT_EQ(runScenario(*model_, *ref_, scenario).walk.steps_completed, 3);
}

// The multipliers of a return map do not depend on the section (poincare.hpp): at the step's
// start and at mid single support, Kelly's gait under HZD (a transversal heel strike, so both
// maps are differentiable) has the same largest multiplier (0.5510 and 0.5509 measured; the
// others are below 6e-4, at the differences' noise), that of its zero dynamics, and the same
// response to a push (the push acts at the same instant of the same step). Optimised
// builds only (about 6 s).
TEST_F(RabbitHzd, MultipliersDoNotDependOnTheSection) {
#ifndef NDEBUG
  GTEST_SKIP() << "two Poincare maps: optimised builds only";
#endif
  PoincareOptions start;
  start.section_clock = 0;
  const PoincareAnalysis a = analysePoincare(*model_, *controller_, *ref_, start);
  const PoincareAnalysis b = analysePoincare(*model_, *controller_, *ref_);  // mid stance
  ASSERT_TRUE(a.ok && b.ok) << a.failure << b.failure;
  EXPECT_NEAR(b.section_clock, ref_->touchdownTime() / 2, 1e-15);
  // Both equal the hybrid zero dynamics' restricted multiplier (the outputs' own are e^-20T).
  const double restricted = restrictedMap(*model_, vc()).multiplier;
  EXPECT_NEAR(a.max_multiplier, restricted, 0.01);
  EXPECT_NEAR(b.max_multiplier, a.max_multiplier, 1e-3);
  EXPECT_NEAR(b.gait_sensitivity_norm, a.gait_sensitivity_norm, 0.01 * a.gait_sensitivity_norm);
  EXPECT_GT(a.gait_sensitivity_norm, 0.017);
}

// A section inside single support must lie past the fade of the step's start (reference.hpp):
// before it the reference still depends on where the step began, which the state leaves out.
TEST_F(RabbitHzd, RefusesASectionBeforeTheFade) {
  PoincareOptions early;
  early.section_clock = ref_->fadeTime() / 2;
  EXPECT_THROW(analysePoincare(*model_, *controller_, *ref_, early), std::invalid_argument);
  early.section_clock = ref_->touchdownTime();
  EXPECT_THROW(analysePoincare(*model_, *controller_, *ref_, early), std::invalid_argument);
}

}  // namespace
}  // namespace gaitopt::sim
