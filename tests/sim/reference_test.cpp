// The reference survives timing errors: past the planned touchdown the swing
// tip keeps descending instead of hovering, and a phase starts from where the robot is with
// derivatives that are the derivatives of the faded angles.
#include <gtest/gtest.h>

#include "dynamics/kinematics.hpp"
#include "five_link_gait.hpp"
#include "sim/controllers/reference.hpp"

namespace gaitopt::sim {
namespace {

using gaits::Phase;

double tipHeight(const gaits::Knot& k) {
  return dynamics::swingTip<double>(test::fiveLinkRobot(), VecD(k.theta))(1);
}

TEST(Reference, PastTouchdownTheSwingTipDescendsAtTheStrikeVelocity) {
  const auto& model = test::fiveLinkRobot();
  const Reference ref(test::polynomialGait(), model, {.strike_velocity = 0.1});
  const double td = ref.touchdownTime();
  const auto at_td = ref.at(Phase::kSsp, td);
  // Mu's gait sets its tip down at rest (3.9-3.10): the planned touchdown is tangential.
  const Vec2d v_td = dynamics::pointVelocity<double>(model.tipWeights(), at_td.theta, at_td.dtheta);
  EXPECT_NEAR(v_td(1), 0.0, 0.02);
  // Past the phase-in window (0.1 s by default) the tip descends at the strike velocity or
  // faster (the change is sized on the rates, linear in the angles, not on the tip), below the
  // touchdown height.
  double last_height = tipHeight(ref.at(Phase::kSsp, td + 0.1));
  EXPECT_LT(last_height, tipHeight(at_td) - 0.002);
  for (double late : {0.1, 0.12, 0.15}) {
    const auto k = ref.at(Phase::kSsp, td + late);
    const Vec2d v = dynamics::pointVelocity<double>(model.tipWeights(), k.theta, k.dtheta);
    EXPECT_LT(v(1), -0.1 + 0.01) << late;
    EXPECT_GT(v(1), -0.1 - 0.02 - 0.5 * (late - 0.1)) << late;
    if (late > 0.1) {
      EXPECT_LT(tipHeight(k), last_height - 0.1 * (late - 0.1) * 0.9) << late;
    }
  }
  // The old reference froze: its tip never got below the planned touchdown height.
  const Reference frozen_like(test::polynomialGait(), model, {.strike_velocity = 0});
  EXPECT_GE(tipHeight(frozen_like.at(Phase::kSsp, td + 0.05)), tipHeight(at_td) - 0.05 * 0.02);
}

TEST(Reference, TheStrikeIsPhasedInWithoutAStepInTheRates) {
  const auto& model = test::fiveLinkRobot();
  const Reference plan(test::polynomialGait());
  const Reference ref(test::polynomialGait(), model,
                      {.strike_velocity = 0.1, .strike_window = 0.1});
  const double td = ref.touchdownTime();
  // Up to the planned touchdown the reference is the plan: a robot on time lands as designed.
  for (double t : {td - 0.15, td}) {
    const auto k = ref.at(Phase::kSsp, t), p = plan.at(Phase::kSsp, t);
    EXPECT_LT((k.theta - p.theta).cwiseAbs().maxCoeff(), 1e-12) << t;
    EXPECT_LT((k.dtheta - p.dtheta).cwiseAbs().maxCoeff(), 1e-12) << t;
  }
  // Rates continuous across the planned touchdown and the window's end.
  for (double at : {td, td + 0.1}) {
    const auto before = ref.at(Phase::kSsp, at - 1e-7), after = ref.at(Phase::kSsp, at + 1e-7);
    EXPECT_LT((after.dtheta - before.dtheta).cwiseAbs().maxCoeff(), 1e-3) << at;
  }
  // Past touchdown the tip goes down further than the unstruck extrapolation's.
  EXPECT_LT(tipHeight(ref.at(Phase::kSsp, td + 0.08)),
            tipHeight(plan.at(Phase::kSsp, td + 0.08)) - 1e-3);
}

TEST(Reference, TheTouchdownAccelerationsFadeOutWithoutAJump) {
  const auto& model = test::fiveLinkRobot();
  const Reference plan(test::polynomialGait());
  const Reference ref(test::polynomialGait(), model, {.strike_velocity = 0.1});
  const double td = ref.touchdownTime();
  // A computed-torque law turns a step in the reference accelerations into a step in the
  // torques and ground forces: none at the planned touchdown (the old reference dropped them
  // to zero there, a step of the plan's full touchdown accelerations).
  const auto before = ref.at(Phase::kSsp, td - 1e-7), after = ref.at(Phase::kSsp, td + 1e-7);
  ASSERT_GT(plan.at(Phase::kSsp, td).ddtheta.cwiseAbs().maxCoeff(), 1.0);
  EXPECT_LT((after.ddtheta - before.ddtheta).cwiseAbs().maxCoeff(), 1e-3);
  // Past the 20 ms fade they are gone (without a model there is no strike to phase in).
  EXPECT_LT(plan.at(Phase::kSsp, td + 0.021).ddtheta.cwiseAbs().maxCoeff(), 1e-12);
  // Rates and angles past touchdown are the integrals of the accelerations (central
  // differences, O(h^2)).
  const double h = 1e-5;
  for (double late : {0.005, 0.015, 0.03, 0.08}) {
    const auto m = ref.at(Phase::kSsp, td + late - h), c = ref.at(Phase::kSsp, td + late),
               p = ref.at(Phase::kSsp, td + late + h);
    EXPECT_LT(((p.dtheta - m.dtheta) / (2 * h) - c.ddtheta).cwiseAbs().maxCoeff(), 1e-3) << late;
    EXPECT_LT(((p.theta - m.theta) / (2 * h) - c.dtheta).cwiseAbs().maxCoeff(), 1e-6) << late;
  }
}

TEST(Reference, APhaseStartsAtTheRobotAndFadesIntoThePlan) {
  const Reference ref(test::polynomialGait(), {.strike_velocity = 0.1, .fade = 0.15});
  const double t0 = 0.1;
  const auto plan = ref.at(Phase::kSsp, t0);
  const VecD theta = VecD(plan.theta) + VecD::Constant(5, 0.03);
  const VecD dtheta = VecD(plan.dtheta) - VecD::Constant(5, 0.4);
  const PhaseStart start = ref.startFrom(Phase::kSsp, t0, theta, dtheta);
  const auto k0 = ref.at(Phase::kSsp, t0, start);
  EXPECT_LT((VecD(k0.theta) - theta).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_LT((VecD(k0.dtheta) - dtheta).cwiseAbs().maxCoeff(), 1e-12);
  const auto after = ref.at(Phase::kSsp, t0 + 0.15, start);
  const auto plain = ref.at(Phase::kSsp, t0 + 0.15);
  EXPECT_LT((after.theta - plain.theta).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_LT((after.dtheta - plain.dtheta).cwiseAbs().maxCoeff(), 1e-12);
  // Rates and accelerations are the time derivatives of the faded angles (central differences
  // minus the plan's own, which is piecewise polynomial at 1 kHz).
  const double h = 1e-5;
  for (double t : {t0 + 0.02, t0 + 0.07, t0 + 0.13}) {
    const auto m = ref.at(Phase::kSsp, t - h, start), c = ref.at(Phase::kSsp, t, start),
               p = ref.at(Phase::kSsp, t + h, start);
    const auto pm = ref.at(Phase::kSsp, t - h), pc = ref.at(Phase::kSsp, t),
               pp = ref.at(Phase::kSsp, t + h);
    const Eigen::VectorXd offset_rate = ((p.theta - pp.theta) - (m.theta - pm.theta)) / (2 * h);
    EXPECT_LT((offset_rate - (c.dtheta - pc.dtheta)).cwiseAbs().maxCoeff(), 1e-6) << t;
    const Eigen::VectorXd offset_acc = ((p.dtheta - pp.dtheta) - (m.dtheta - pm.dtheta)) / (2 * h);
    EXPECT_LT((offset_acc - (c.ddtheta - pc.ddtheta)).cwiseAbs().maxCoeff(), 1e-4) << t;
  }
}

TEST(Reference, RejectsOptionsOutOfRange) {
  EXPECT_THROW(Reference(test::polynomialGait(), {.strike_velocity = -0.1}), std::invalid_argument);
  EXPECT_THROW(Reference(test::polynomialGait(), {.fade = 0}), std::invalid_argument);
  EXPECT_THROW(Reference(test::polynomialGait(), {.strike_window = -1}), std::invalid_argument);
}

}  // namespace
}  // namespace gaitopt::sim
