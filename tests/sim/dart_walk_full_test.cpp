// The gait designed to be walked (configs/ocp/mu2004_walk_robust.yaml) under Mu's sliding mode in
// DART (sim/contact/dart_walk.hpp), on plants 10 % lighter and heavier than the model: it walks,
// its feet stay on the floor, and over the steps the floor carries the robot's weight.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "dynamics/model_variation.hpp"
#include "dynamics/robot_files/robot_config.hpp"
#include "dynamics/robot_files/urdf_export.hpp"
#include "ocp/guess/initial_guess.hpp"
#include "ocp/solve/gait_solve.hpp"
#include "sim/contact/ground_config.hpp"
#include "sim/controllers/mu_sliding_mode.hpp"
#include "sim/walk/walk.hpp"

namespace gaitopt::sim {
namespace {

/// What the floor did over a walk in DART.
struct FloorRecord {
  double deepest = 0;    ///< deepest stance tip below the floor's surface [m]
  double impulse_y = 0;  ///< sum of the vertical floor forces times the time step [N s]
  double impulse_x = 0;  ///< the same along the floor [N s]
  double duration = 0;   ///< time over which they were summed [s]
};

class DartWalkFull : public ::testing::TestWithParam<double> {
 protected:
  static void SetUpTestSuite() {
#ifndef NDEBUG
    return;
#endif
    const auto config = ocp::loadOcpConfig(std::string(GAITOPT_SOURCE_DIR) +
                                           "/configs/ocp/mu2004_walk_robust.yaml");
    nominal_ = new dynamics::Model(dynamics::loadRobot(config.robot_path));
    const auto solution =
        ocp::solveGait(*nominal_, config, ocp::polynomialGuess(*nominal_, config));
    ASSERT_TRUE(solution.result.success) << solution.result.status;
    reference_ = new Reference(
        ocp::reconstructDense(solution.problem, *nominal_, solution.result.x, 1000.0), *nominal_);
  }
  static void TearDownTestSuite() {
    delete reference_;
    delete nominal_;
  }
  static dynamics::Model* nominal_;
  static Reference* reference_;
};
dynamics::Model* DartWalkFull::nominal_ = nullptr;
Reference* DartWalkFull::reference_ = nullptr;

TEST_P(DartWalkFull, TheRobustOptimumWalksTwentySteps) {
#ifndef NDEBUG
  GTEST_SKIP() << "an OCP solve and a walk of 20 steps: optimised builds only";
#endif
  ASSERT_NE(reference_, nullptr) << "the robust optimum did not solve";
  const double mass_error = GetParam();
  const dynamics::Model plant = dynamics::perturbedModel(*nominal_, {mass_error, mass_error, 0, 0});
  const MuSlidingModeController controller(*nominal_, muTable42(1), {0.2, 0.2, 0.05, 0.05});
  const auto ground = loadGround(std::string(GAITOPT_SOURCE_DIR) + "/configs/grounds/dart.yaml");
  const double h = ground.getIf<DartGround>()->time_step;
  FloorRecord floor;
  // From the second step on: the first starts from the plan's state, not from a step of DART's.
  const auto log = [&](const WalkSample& s) {
    floor.deepest = std::max(floor.deepest, -s.stance_y);
    if (s.step == 0) return;
    floor.impulse_y += h * (s.force_stance(1) + s.force_swing(1));
    floor.impulse_x += h * (s.force_stance(0) + s.force_swing(0));
    floor.duration += h;
  };
  ContactRules rules;
  rules.cop_limit = CopLimit::kFail;
  const WalkResult w = walk(plant, controller, *reference_, ground, {20, {}, rules}, log);
  EXPECT_EQ(w.steps_completed, 20) << w.failure;
  EXPECT_LT(w.max_slip, 0.001) << "measured 0.15 mm";
  EXPECT_LT(floor.deepest, 0.001) << "measured 0.45 mm: DART's contacts hold the feet on the floor";
  // Momentum balance over 19 steps of a periodic walk: the floor's impulse carries the weight
  // (the feet of the URDF included) and no net push along the floor, to within what the body's
  // momentum differs between the first and last step's start.
  const double weight = (plant.totalMass() + 2 * dynamics::kExportFoot.mass) * plant.gravity();
  EXPECT_NEAR(floor.impulse_y / (weight * floor.duration), 1.0, 1e-3) << "measured 2e-5 off";
  EXPECT_LT(std::abs(floor.impulse_x) / (weight * floor.duration), 2e-3) << "measured 2.6e-4";
}

INSTANTIATE_TEST_SUITE_P(PlantMass, DartWalkFull, ::testing::Values(-0.1, 0.0, 0.1));

}  // namespace
}  // namespace gaitopt::sim
