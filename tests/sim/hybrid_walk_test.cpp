// Closed-loop walking on rigid ground: the tracking controllers on the exact model add nothing to
// the reference's torques (polynomial and optimal five-link gaits), walk the polynomial gait for
// 20 planned steps, and the Poincare multipliers of the cycle lie inside the unit circle.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include "dynamics/robot_config.hpp"
#include "ocp/gait_solve.hpp"
#include "ocp/initial_guess.hpp"
#include "sim/hybrid_walk.hpp"
#include "sim/poincare.hpp"

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
  }
  static void TearDownTestSuite() {
    delete optimal_;
    delete poly_;
    delete model_;
  }
  static TrackingController controller(const std::string& law) {
    return TrackingController(*model_, makeTrackingLaw(law, TrackingGains{}));
  }
  static dynamics::Model* model_;
  static gaits::Trajectory *poly_, *optimal_;
};
dynamics::Model* FiveLinkWalk::model_ = nullptr;
gaits::Trajectory* FiveLinkWalk::poly_ = nullptr;
gaits::Trajectory* FiveLinkWalk::optimal_ = nullptr;

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

#ifdef NDEBUG
constexpr int kSteps = 20;
#else  // unoptimised sanitizer builds are ~1000x slower: a short walk, no Poincare map there
constexpr int kSteps = 2;
#endif

TEST_F(FiveLinkWalk, PolynomialGaitWalksTwentyStepsOnAStableCycle) {
  // (The optimal gait is not walked here yet: its swing tip grazes the ground between the
  // collocation points, where clearance 0 is not enforced, and touches down early.)
  for (const auto* traj : {poly_}) {
    const Reference ref(*traj);
    for (const std::string law : {"computed_torque", "sliding_mode"}) {
      const TrackingController c = controller(law);
      WalkOptions options;
      options.steps = kSteps;
      const WalkResult w = simulateWalk(*model_, c, ref, options);
      EXPECT_EQ(w.steps_completed, kSteps) << law << ": " << w.failure;
      if (kSteps < 20) continue;
      const PoincareAnalysis p = analysePoincare(*model_, c, ref);
      ASSERT_TRUE(p.ok) << p.failure;
      RecordProperty(law + "_max_multiplier", fmt::format("{:.4f}", p.max_multiplier));
      RecordProperty(law + "_tracking_error", fmt::format("{:.2e}", w.max_tracking_error));
      for (const auto& step : w.steps) {  // the planned step: touchdown at 0.6 s, 0.35 m ahead
        EXPECT_EQ(step.impact, "double");
        EXPECT_NEAR(step.ssp_duration, ref.touchdownTime(), 2e-3);
        EXPECT_NEAR(step.advance, ref.stepLength(), 1e-3);
      }
      EXPECT_LT(p.max_multiplier, 1.0) << law;
      EXPECT_LT(p.fixed_point_residual, 1e-6) << law;
    }
  }
}

}  // namespace
}  // namespace gaitopt::sim
