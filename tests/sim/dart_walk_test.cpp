// The polynomial gait of Mu (2004) under computed torque in DART (sim/contact/dart_walk.hpp): the
// robot exported as a URDF, its box feet on DART's floor, the loop closed at 2 kHz. Single support
// tracks the gait on DART's state, and the stance foot rests on the floor as on a rigid one: it
// neither sinks nor slides while its force stays inside the friction cone. RABBIT's point feet
// pivot as the model's tips do. (Walks of several steps, of the gait designed to be walked:
// dart_walk_full_test.cpp.)
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "dynamics/robot_files/urdf_export.hpp"
#include "five_link_gait.hpp"
#include "sim/contact/ground_config.hpp"
#include "sim/controllers/hzd_controller.hpp"
#include "sim/walk/walk.hpp"
#include "support/solved_config.hpp"

namespace gaitopt::sim {
namespace {

TEST(DartWalk, SingleSupportTracksTheGaitWithTheStanceFootAtRest) {
  const Reference ref(test::polynomialGait());
  const GroundModel ground =
      loadGround(std::string(GAITOPT_SOURCE_DIR) + "/configs/grounds/dart.yaml");
  const dynamics::Model& plant = test::longHeelRobot();
  double error = 0, depth = 0, load = 0, slide = 0, friction_ratio = 0;
  double x0 = std::nan("");
  int samples = 0;
  const double weight = plant.totalMass() * plant.gravity();
  const auto log = [&](const WalkSample& s) {
    if (s.step != 0 || s.t < 0.05 || s.t > 0.5) return;  // after the settling
    ++samples;
    if (std::isnan(x0)) x0 = s.stance_x;
    error = std::max(error, (s.theta - s.theta_ref).cwiseAbs().maxCoeff());
    depth = std::max(depth, -s.stance_y);
    load = std::max(load, std::abs(s.force_stance(1) - weight) / weight);
    slide = std::max(slide, std::abs(s.stance_x - x0));
    friction_ratio = std::max(friction_ratio, std::abs(s.force_stance(0) / s.force_stance(1)));
  };
  const WalkResult w = walk(plant, test::computedTorque(), ref, ground, {1, {}, {}}, log);
  EXPECT_EQ(samples, 900) << "the loop closes at 2 kHz through 0.05..0.5 s of single support";
  EXPECT_LT(error, 0.01) << "measured 0.0054 rad";
  EXPECT_LT(load, 0.1) << "the stance foot carries the weight (a swing foot of 0.05 kg aside)";
  // A rigid floor with Coulomb friction: no sinking, and no sliding inside the cone.
  ASSERT_LT(friction_ratio, plant.friction());
  EXPECT_LT(depth, 2e-5)
      << "measured 1.3e-6 m (3.7 mm with friction across the plane, dart_walk.cpp)";
  EXPECT_LT(slide, 1e-5) << "measured 8e-8 m";
  EXPECT_LT(w.max_foot_tilt, 1e-3) << "the loaded foot lies flat";
}

// On the shipped 5 cm heel the same gait asks for a centre of pressure up to 0.197 m behind the
// tip (five_link_gait.hpp): in DART the foot is a body, and it tips back onto its heel (measured
// 0.37 rad) before the stance tip slides off its mark.
TEST(DartWalk, AFootAskedForACentreOfPressureOffItTips) {
  const GroundModel ground =
      loadGround(std::string(GAITOPT_SOURCE_DIR) + "/configs/grounds/dart.yaml");
  const WalkResult w = walk(test::fiveLinkRobot(), test::computedTorque(),
                            Reference(test::polynomialGait()), ground, {1, {}, {}});
  EXPECT_EQ(w.steps_completed, 0);
  EXPECT_GT(w.max_foot_tilt, 0.2);
}

/// Kelly's optimum for RABBIT (configs/ocp/rabbit_kelly2017.yaml, about 0.1 s), solved once.
struct RabbitOptimum {
  dynamics::Model model;
  gaits::Trajectory gait;
};
const RabbitOptimum& rabbitOptimum() {
  static const RabbitOptimum optimum = [] {
    const gaitopt::test::SolvedConfig rabbit(
        ocp::loadOcpConfig(gaitopt::test::shippedOcpConfig("rabbit_kelly2017")));
    if (!rabbit.result.success) throw std::runtime_error(rabbit.result.status);
    return RabbitOptimum{
        rabbit.model, ocp::reconstructDense(rabbit.problem, rabbit.model, rabbit.result.x, 1000.0)};
  }();
  return optimum;
}

/// RABBIT's optimum under HZD in DART along `plan`.
WalkResult rabbitInDart(const WalkPlan& plan) {
  const Reference ref(rabbitOptimum().gait);
  const dynamics::Model& model = rabbitOptimum().model;
  const auto controller = makeHzdController(model, ref, std::make_unique<PdLaw>(TrackingGains{}));
  const GroundModel ground =
      loadGround(std::string(GAITOPT_SOURCE_DIR) + "/configs/grounds/dart.yaml");
  return walk(model, *controller, ref, ground, plan);
}

// A point foot is a ball on a locked ankle (dart_walk.hpp): the model's tip is a pivot, and the
// ball only rolls its centre by its radius per radian the shank turns. RABBIT's optimum under
// HZD walks 10 steps in DART with each stance tip within that roll of where it landed. On a
// free ankle hinge the ball was a wheel: the stance tip rolled 9.8 mm within 51 ms and the walk
// failed in step 1.
TEST(DartWalk, PointFeetPivotAsTheModelsTipsDo) {
  const WalkResult w = rabbitInDart({10, {}, {}});
  ASSERT_EQ(w.steps_completed, 10) << w.failure;
  double lowest = INFINITY, highest = -INFINITY;  // the stance shank's sweep over a step
  for (const gaits::Knot& k : rabbitOptimum().gait.knots()) {
    lowest = std::min(lowest, k.theta(0));
    highest = std::max(highest, k.theta(0));
  }
  const double roll = dynamics::kExportFoot.radius * (highest - lowest);
  EXPECT_LT(w.max_slip, roll + 2e-4) << "the ball's roll " << roll << " m; measured 2.162 mm of "
                                     << "a 2.166 mm roll";
  EXPECT_NEAR(completedTotals(w).distance / 10, rabbitOptimum().gait.stepLength(), 1e-3);
}

// A push DART's walk cannot absorb: 40 N s forward on the hip (a 0.1 s pulse from mid single
// support of step 2; 1.25 m/s on the robot's 32 kg) lifts the stance tip within a step of it,
// where 4 N s is walked through.
TEST(DartWalk, ALargePushMakesRabbitFall) {
  const auto pushed = [](double impulse) {
    Push push;  // step 2, from mid single support, 0.1 s
    push.impulse = Vec2d(impulse, 0);
    return rabbitInDart({6, push, {}});
  };
  const WalkResult small = pushed(4);
  EXPECT_EQ(small.steps_completed, 6) << small.failure;
  const WalkResult w = pushed(40);
  EXPECT_GE(w.steps_completed, 1) << "the step before the push";
  EXPECT_LE(w.steps_completed, 2) << w.failure;
  EXPECT_NE(w.failure.find(kStanceLiftoff), std::string::npos) << w.failure;
}

}  // namespace
}  // namespace gaitopt::sim
