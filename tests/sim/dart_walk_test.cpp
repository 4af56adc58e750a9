// The polynomial gait of Mu (2004) under computed torque in DART (sim/contact/dart_walk.hpp): the
// robot exported as a URDF, its box feet on DART's floor, the loop closed at 1 kHz. Single support
// tracks the gait on DART's state; the first touchdown does not yet hold (a slip, docs).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "five_link_gait.hpp"
#include "sim/contact/ground_config.hpp"
#include "sim/walk/walk.hpp"

namespace gaitopt::sim {
namespace {

TEST(DartWalk, SingleSupportTracksTheGaitOnDartsState) {
  const Reference ref(test::polynomialGait());
  const GroundModel ground =
      loadGround(std::string(GAITOPT_SOURCE_DIR) + "/configs/grounds/dart.yaml");
  const dynamics::Model& plant = test::longHeelRobot();
  double error = 0, depth = 0, load = 0;
  int samples = 0;
  const double weight = plant.totalMass() * plant.gravity();
  const auto log = [&](const WalkSample& s) {
    if (s.step != 0 || s.t < 0.05 || s.t > 0.5) return;  // after the settling
    ++samples;
    error = std::max(error, (s.theta - s.theta_ref).cwiseAbs().maxCoeff());
    depth = std::max(depth, -s.stance_y);
    load = std::max(load, std::abs(s.force_stance(1) - weight) / weight);
  };
  walk(plant, test::computedTorque(), ref, ground, {1, {}, {}}, log);
  EXPECT_EQ(samples, 450) << "the loop closes at 1 kHz through 0.05..0.5 s of single support";
  EXPECT_LT(error, 0.01) << "measured 0.0056 rad";
  EXPECT_LT(depth, 0.005) << "measured 3.7 mm: the flat foot rests on the floor";
  EXPECT_LT(load, 0.1) << "the stance foot carries the weight (a swing foot of 0.05 kg aside)";
}

}  // namespace
}  // namespace gaitopt::sim
