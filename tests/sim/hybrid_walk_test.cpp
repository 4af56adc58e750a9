// Closed-loop walking on rigid ground: the tracking controllers on the exact model add nothing to
// the reference's torques (polynomial and optimal five-link gaits), and with the plan's
// double-support torques a wrong model commands the plan on the reference; they walk both gaits
// for 20 planned steps, and the Poincare multipliers of each cycle lie inside the unit circle.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <utility>

#include <fmt/format.h>

#include "dynamics/model_variation.hpp"
#include "dynamics/robot_files/robot_config.hpp"
#include "ocp/guess/initial_guess.hpp"
#include "ocp/solve/gait_solve.hpp"
#include "sim/controllers/mu_sliding_mode.hpp"
#include "sim/scenario/scenario.hpp"
#include "sim/scenario/scenario_settings.hpp"
#include "sim/studies/poincare.hpp"
#include "sim/walk/event_integrator.hpp"
#include "sim/walk/hybrid_walk.hpp"
#include "support/shipped_export.hpp"

namespace gaitopt::sim {
namespace {

const std::string kOcp = std::string(GAITOPT_SOURCE_DIR) + "/configs/ocp/mu2004_walk.yaml";

class FiveLinkWalk : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    const auto config = ocp::loadOcpConfig(kOcp);
    model_ = new dynamics::Model(dynamics::loadRobot(config.robot_path));
    poly_ = new gaits::Trajectory(ocp::polynomialGuess(*model_, config));
    const auto solution = ocp::solveGait(*model_, config, *poly_);
    // At its collocation points, where the optimum satisfies the dynamics.
    optimal_ =
        new gaits::Trajectory(ocp::reconstruct(solution.problem, *model_, solution.result.x));
    // What `gaitopt optimize` exports (trajectory.csv): the scheme's polynomials at 1 kHz.
    optimal_export_ = new gaits::Trajectory(
        ocp::reconstructDense(solution.problem, *model_, solution.result.x, 1000.0));
  }
  static void TearDownTestSuite() {
    delete optimal_export_;
    delete optimal_;
    delete poly_;
    delete model_;
  }
  /// computed_torque (PD) or sliding_mode (controller_registry.cpp), default gains.
  static TrackingController controller(const std::string& law) {
    const TrackingGains gains;
    if (law == "sliding_mode")
      return TrackingController(*model_, std::make_unique<SlidingModeLaw>(gains));
    return TrackingController(*model_, std::make_unique<PdLaw>(gains));
  }
  static dynamics::Model* model_;
  static gaits::Trajectory *poly_, *optimal_, *optimal_export_;
};
dynamics::Model* FiveLinkWalk::model_ = nullptr;
gaits::Trajectory* FiveLinkWalk::poly_ = nullptr;
gaits::Trajectory* FiveLinkWalk::optimal_ = nullptr;
gaits::Trajectory* FiveLinkWalk::optimal_export_ = nullptr;

TEST_F(FiveLinkWalk, OnTheReferenceTheControllersAddNoTorqueToTheFeedForward) {
  for (const std::string law : {"computed_torque", "sliding_mode"}) {
    const TrackingController c = controller(law);
    double worst = 0;
    for (const auto* traj : {poly_, optimal_})
      for (const auto& k : traj->knots())
        worst = std::max(
            worst,
            (c.unclippedTorque(k.phase, k.theta, k.dtheta, k) - VecD(k.tau)).cwiseAbs().maxCoeff());
    RecordProperty(law + "_feedback_torque_on_reference", fmt::format("{:.2e}", worst));
    EXPECT_LT(worst, 1e-8) << law;
  }
}

/// The largest |torque(knot) - the knot's torques| over the reference's double-support knots.
template <class Torque>
double largestDspDeparture(const gaits::Trajectory& ref, const Torque& torque) {
  double worst = 0;
  for (const auto& k : ref.knots())
    if (k.phase == gaits::Phase::kDsp)
      worst = std::max(worst, (torque(k) - VecD(k.tau)).cwiseAbs().maxCoeff());
  return worst;
}

// The plan's feed-forward in double support (DspFeedForward::kPlan) takes the torques from the
// reference, computed on the true model, so a controller whose model is off (computed torque by
// Mu's case 2: +40 % masses and inertias, +10 % lengths; Mu's law by case 3: +100 %, +40 %)
// still commands them on the reference, where its model's own torques are off by newton-metres.
// On the reference Mu's law has s = 0 at z = 0, so its switching term (4.14) vanishes; the T_c
// carried from the single support is left at zero here.
TEST_F(FiveLinkWalk, ThePlansDoubleSupportFeedForwardIgnoresAWrongModel) {
  const auto tracking = [&](DspFeedForward dsp) {
    const dynamics::Model wrong = dynamics::perturbedModel(*model_, dynamics::muUncertaintyCase(2));
    const TrackingController c(wrong, std::make_unique<PdLaw>(TrackingGains{}), dsp);
    return largestDspDeparture(*poly_, [&](const gaits::Knot& k) {
      return c.unclippedTorque(k.phase, k.theta, k.dtheta, k);
    });
  };
  const auto mu = [&](DspFeedForward dsp) {
    const dynamics::Model wrong = dynamics::perturbedModel(*model_, dynamics::muUncertaintyCase(3));
    const MuSlidingModeController c(wrong, muTable42(3), {}, BoundSide::kEitherWay, dsp);
    const Eigen::VectorXd memory = Eigen::VectorXd::Zero(c.memorySize(gaits::Phase::kDsp));
    return largestDspDeparture(*poly_, [&](const gaits::Knot& k) {
      return c.unclippedTorque(k.phase, k.theta, k.dtheta, k, memory);
    });
  };
  const std::pair<const char*, std::function<double(DspFeedForward)>> laws[] = {
      {"computed_torque", tracking}, {"mu_sliding_mode", mu}};
  for (const auto& [name, departure] : laws) {
    const double plan = departure(DspFeedForward::kPlan);
    const double model = departure(DspFeedForward::kModel);
    RecordProperty(fmt::format("{}_plan_error_Nm", name), fmt::format("{:.2e}", plan));
    RecordProperty(fmt::format("{}_model_error_Nm", name), fmt::format("{:.2f}", model));
    EXPECT_LT(plan, 1e-8) << name;
    EXPECT_GT(model, 1.0) << name;
  }
}

// A step that blows up inside one RK4 step is a divergence, and the walk ends at the last state
// before it: the optimum walked by a robot whose torso CoM sits at 0.1 m (not 0.282) slides its
// stance tip into a singular contact (a Painleve case), where one event-location step made
// 5e27 N on the tip, put the hip 4.9 km off and was recorded as "fall: hip below its limit" with
// that slip and an 11 693 rad tracking error.
TEST_F(FiveLinkWalk, AStepThatBlowsUpIsADivergenceAndLeavesNothingOfItInTheRecord) {
  const dynamics::Model plant =
      dynamics::loadRobot(ocp::loadOcpConfig(kOcp).robot_path, {{"links[2].com", "0.1"}});
  const TrackingController c(plant, std::make_unique<PdLaw>(TrackingGains{}));
  WalkOptions options;
  options.steps = 2;
  double largest_force = 0;
  bool finite = true;
  const WalkResult w =
      simulateWalk(plant, c, Reference(*optimal_export_), options, [&](const WalkSample& s) {
        finite = finite && s.theta.allFinite() && s.tau.allFinite();
        largest_force = std::max({largest_force, s.force_stance.norm(), s.force_swing.norm()});
      });
  RecordProperty("failure", w.failure);
  RecordProperty("max_slip_m", fmt::format("{:.3g}", w.max_slip));
  RecordProperty("largest_logged_force_N", fmt::format("{:.4g}", largest_force));
  EXPECT_EQ(w.steps_completed, 0);
  EXPECT_NE(w.failure.find("diverged"), std::string::npos) << w.failure;
  EXPECT_LT(w.max_slip, 0.01);
  EXPECT_LT(w.max_tracking_error, 0.1);
  EXPECT_TRUE(finite);
  EXPECT_LT(largest_force, 1000.0);  // the robot weighs 292 N
}

// The integrator's side of it: a step the check refuses ends the integration at the last
// accepted state, the one the observer saw last, whether or not its garbage fired an event.
TEST(EventIntegrator, ARefusedStepEndsAtTheLastAcceptedStateUnobserved) {
  // x' = 0, but 1e30 from t = 0.24 (a blow-up): the RK4 step from t = 0.2 ends at garbage.
  const Rhs f = [](double t, const Eigen::VectorXd&) {
    return Eigen::VectorXd::Constant(1, t < 0.24 ? 0.0 : 1e30);
  };
  const StepCheck bounded = [](double, const Eigen::VectorXd&, double, const Eigen::VectorXd& x) {
    return std::abs(x(0)) < 1e6 ? std::string() : std::string("garbage");
  };
  const Events never = [](double, const Eigen::VectorXd&) { return Eigen::VectorXd::Ones(1); };
  const Events above = [](double, const Eigen::VectorXd& x) {
    return Eigen::VectorXd::Constant(1, 1 - x(0));
  };
  for (const Events& g : {never, above}) {
    double last_seen = 0;
    const EventIntegration end = integrateToEvent(
        f, g, 0, Eigen::VectorXd::Zero(1), 1, {0.1, 1e-10},
        [&](double t, const Eigen::VectorXd&) { last_seen = t; }, bounded);
    EXPECT_EQ(end.failure, "garbage");
    EXPECT_EQ(end.event, -1);
    EXPECT_NEAR(end.t, 0.2, 1e-12);
    EXPECT_EQ(end.x(0), 0.0);
    EXPECT_EQ(last_seen, end.t);
  }
}

#ifdef NDEBUG
constexpr int kSteps = 20;
#else  // unoptimised sanitizer builds are ~1000x slower: a short walk, no Poincare map there
constexpr int kSteps = 2;
#endif

TEST_F(FiveLinkWalk, BothGaitsWalkTwentyStepsOnAStableCycleOnALongHeel) {
  // The planned step: touchdown at 0.6 s, 0.35 m ahead, on both the polynomial gait and the
  // optimum as exported (trajectory.csv at 1 kHz). Both set the swing tip down at rest, so the
  // simulator's contact threshold (1 um above the ground) is reached early: measured 0.67 ms
  // (polynomial) and 0.26 ms (optimal), advance within 4e-6 m. With clearance 0 between the
  // optimum's points it touched down at 0.537 s; with friction margin 0.1 computed torque
  // slipped at the start of the double support, where the trailing tip carries only 55-75 N.
  const std::pair<std::string, const gaits::Trajectory*> gaits[] = {{"polynomial", poly_},
                                                                    {"optimal", optimal_export_}};
  // Both walk a 0.30 m heel. The polynomial gait's ZMP lies up to 0.197 m behind the stance tip:
  // on the shipped 0.05 m heel its ankle saturates and it falls (contact_walk_test.cpp). The
  // optimum keeps its CoP 5 cm inside the foot at every integrator step (--cop-limit fail walks),
  // but between its 1 kHz samples the quintic interpolation (gaits/trajectory/trajectory.cpp) of
  // the export overshoots: at t = 0.58275 s it gives ddtheta1 = 23.8 rad/s^2 between samples of 3.2
  // and 2.7, so computed torque asks the ankle for +13 N m (-10 N m at the samples) at the RK4
  // midpoints. Clipped at the 5 cm heel, the swing tip stays 40 um up at the planned touchdown and
  // the stance tip slides 1 cm (measured: the reference, not the ground, is at fault).
  const dynamics::Model plant = dynamics::withFoot(*model_, {0.30, model_->foot().toe});
  for (const auto& [name, step] : gaits) {
    const Reference ref(*step);
    for (const std::string law : {"computed_torque", "sliding_mode"}) {
      const std::string label = name + "_" + law;
      const TrackingController c = controller(law);
      WalkOptions options;
      options.steps = kSteps;
      const WalkResult w = simulateWalk(plant, c, ref, options);
      EXPECT_EQ(w.steps_completed, kSteps) << label << ": " << w.failure;
      double touchdown_error = 0, advance_error = 0;
      for (const auto& s : w.steps) {
        EXPECT_EQ(s.impact, "double") << label;
        touchdown_error = std::max(touchdown_error, std::abs(s.ssp_duration - ref.touchdownTime()));
        advance_error = std::max(advance_error, std::abs(s.advance - ref.stepLength()));
      }
      RecordProperty(label + "_tracking_error", fmt::format("{:.2e}", w.max_tracking_error));
      RecordProperty(label + "_touchdown_error_s", fmt::format("{:.2e}", touchdown_error));
      RecordProperty(label + "_advance_error_m", fmt::format("{:.2e}", advance_error));
      EXPECT_LT(touchdown_error, 2e-3) << label;
      EXPECT_LT(advance_error, 1e-4) << label;
      if (kSteps < 20) continue;
      const PoincareAnalysis p = analysePoincare(plant, c, ref);
      ASSERT_TRUE(p.ok) << label << ": " << p.failure;
      RecordProperty(label + "_max_multiplier", fmt::format("{:.4f}", p.max_multiplier));
      EXPECT_LT(p.max_multiplier, 1.0) << label;
      EXPECT_LT(p.fixed_point_residual, 1e-6) << label;
    }
  }
  // Said, not passed in silence: the name's twenty steps and stable cycle were not checked.
  if (kSteps < 20)
    GTEST_SKIP() << kSteps << " steps walked; twenty and the Poincare map need an optimised build";
}

// The rigid ground has touchdown only ahead of the stance tip: a swing tip below the ground
// behind it is no contact, and the walk goes on through the floor. Which walks fail stays as it
// was; the walk measures how deep (StepResult::max_tip_penetration). The robust optimum under
// Mu's law with the plant's masses 40 % over (`simulate --controller mu_sliding_mode
// --mass-error 0.4`): the old trailing tip goes 0.54 mm below the ground behind B in every step,
// and all steps are walked; walked nominally, by the default controller, it stays within the
// 1e-6 m above the ground at which touchdown is detected (rigid_step.cpp kContactDistance).
TEST(RigidWalk, ASwingTipBelowTheGroundBehindTheStanceTipIsMeasuredNotFailed) {
#ifndef NDEBUG
  GTEST_SKIP() << "an OCP solve and two walks: optimised builds only";
#endif
  const gaitopt::test::ShippedExport robust = gaitopt::test::shippedExport("mu2004_walk_robust");
  ASSERT_TRUE(robust.success) << robust.status;
  const dynamics::Model& nominal = robust.model;
  const Reference ref(robust.dense, nominal);
  ScenarioSettings settings;
  settings.steps = 4;
  const ScenarioResult plain = runScenario(nominal, ref, makeScenario(settings));
  EXPECT_EQ(plain.walk.steps_completed, settings.steps) << plain.walk.failure;
  EXPECT_LT(plain.walk.max_tip_penetration, 1e-6);
  EXPECT_GE(plain.walk.max_tip_penetration, 0.0);

  settings.controller = "mu_sliding_mode";
  settings.mass_error = 0.4;
  const ScenarioResult heavy = runScenario(nominal, ref, makeScenario(settings));
  RecordProperty("max_tip_penetration_m", std::to_string(heavy.walk.max_tip_penetration));
  EXPECT_EQ(heavy.walk.steps_completed, settings.steps) << heavy.walk.failure;
  EXPECT_GT(heavy.walk.max_tip_penetration, 1e-4);
  ASSERT_EQ(heavy.walk.steps.size(), 4u);
  for (const StepResult& s : heavy.walk.steps) EXPECT_GT(s.max_tip_penetration, 1e-4);
  EXPECT_GE(deepestPenetrationStep(heavy.walk), 1);
}

}  // namespace
}  // namespace gaitopt::sim
