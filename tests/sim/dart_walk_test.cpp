// The polynomial gait of Mu (2004) under computed torque in DART (sim/contact/dart_walk.hpp): the
// robot exported as a URDF, its box feet on DART's floor, the loop closed at 2 kHz. Single support
// tracks the gait on DART's state, and the stance foot rests on the floor as on a rigid one: it
// neither sinks nor slides while its force stays inside the friction cone. (Walks of several
// steps, of the gait designed to be walked: dart_walk_full_test.cpp.)
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "five_link_gait.hpp"
#include "sim/contact/ground_config.hpp"
#include "sim/walk/walk.hpp"

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
  walk(plant, test::computedTorque(), ref, ground, {1, {}, {}}, log);
  EXPECT_EQ(samples, 900) << "the loop closes at 2 kHz through 0.05..0.5 s of single support";
  EXPECT_LT(error, 0.01) << "measured 0.0054 rad";
  EXPECT_LT(load, 0.1) << "the stance foot carries the weight (a swing foot of 0.05 kg aside)";
  // A rigid floor with Coulomb friction: no sinking, and no sliding inside the cone.
  ASSERT_LT(friction_ratio, plant.friction());
  EXPECT_LT(depth, 2e-5)
      << "measured 1.3e-6 m (3.7 mm with friction across the plane, dart_walk.cpp)";
  EXPECT_LT(slide, 1e-5) << "measured 8e-8 m";
}

}  // namespace
}  // namespace gaitopt::sim
