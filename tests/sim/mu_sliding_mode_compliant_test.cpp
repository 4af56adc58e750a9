// Mu's sliding-mode controller (2004, ch. 4) at a touchdown on the compliant ground
// (configs/grounds/impedance.yaml): the tips sink ~1 mm under the robot, so the swing tip meets
// the ground ~20 ms before the plan and the double support starts off its reference. The
// integral of (4.1) then starts where the sliding surface passes through the robot
// (phaseStartMemory), so the switching term (4.14) does not fight that start, and the leading
// tip takes the load over instead of being pulled off the ground.
#include <gtest/gtest.h>

#include <algorithm>

#include "five_link_gait.hpp"
#include "sim/contact/ground_config.hpp"
#include "sim/controllers/mu_sliding_mode.hpp"
#include "sim/walk/walk.hpp"

namespace gaitopt::sim {
namespace {

using gaits::Phase;

/// The uncertainty bound `gaitopt simulate` gives the controller (scenario.hpp).
const dynamics::ParameterErrors kBound{0.2, 0.2, 0.05, 0.05};

TEST(MuSlidingModeCompliant, APhaseStartsWithTheSlidingVariableAtZero) {
  const auto& model = test::fiveLinkRobot();
  const Reference ref(test::polynomialGait(), model);
  const MuSlidingModeController c(model, muTable42(1), kBound);
  // A robot 0.02 rad and 0.5 rad/s off the DSP's first knot, as an early touchdown leaves it.
  const gaits::Knot k = ref.at(Phase::kDsp, ref.touchdownTime());
  const VecD theta = VecD(k.theta) + 0.02 * VecD::LinSpaced(5, -1, 1).cwiseAbs2();
  const VecD dtheta = VecD(k.dtheta) - 0.5 * VecD::LinSpaced(5, -1, 1);
  for (const Phase phase : {Phase::kSsp, Phase::kDsp}) {
    const Eigen::VectorXd z = c.phaseStartMemory(phase, theta, dtheta, k, nullptr);
    ASSERT_EQ(z.size(), c.memorySize(phase));
    EXPECT_LT(c.slidingVariable(phase, theta, dtheta, k, z).cwiseAbs().maxCoeff(), 1e-12);
    EXPECT_GT(c.slidingVariable(phase, theta, dtheta, k, 0 * z).cwiseAbs().maxCoeff(), 0.1);
  }
}

TEST(MuSlidingModeCompliant, TheLeadingTipTakesTheLoadOverAtAnEarlyTouchdown) {
  const auto& plant = test::longHeelRobot();  // the polynomial gait's ZMP needs a 0.2 m heel
  const Reference ref(test::polynomialGait(), plant);
  const MuSlidingModeController c(plant, muTable42(1), kBound);
  const GroundModel ground =
      loadGround(std::string(GAITOPT_SOURCE_DIR) + "/configs/grounds/impedance.yaml");
  // The first double support: E's normal force from 1 ms after touchdown (the first samples
  // are the Hunt-Crossley force rising from zero) until the trailing tip B has unloaded.
  double touchdown = -1, b_unloaded = -1, e_least = 1e9, e_most = 0;
  const auto log = [&](const WalkSample& s) {
    if (s.step != 0 || s.phase != Phase::kDsp) return;
    if (touchdown < 0) touchdown = s.t;
    if (b_unloaded < 0 && s.force_stance(1) <= 0) b_unloaded = s.t;
    if (s.t < touchdown + 1e-3 || b_unloaded >= 0) return;
    e_least = std::min(e_least, s.force_swing(1));
    e_most = std::max(e_most, s.force_swing(1));
  };
  const WalkResult w = walk(plant, c, ref, ground, {1, {}, {}}, log);
  RecordProperty("touchdown_s", std::to_string(touchdown));
  RecordProperty("leading_tip_least_force_N", std::to_string(e_least));
  ASSERT_GE(touchdown, 0) << "no touchdown";
  // The early touchdown this test is about: the tips sink ~1 mm, E meets them ~20 ms early.
  EXPECT_LT(touchdown, ref.touchdownTime() - 0.01);
  // From z = 0 the switching term (4.14) asked the ground to pull E (-900 N on the rigid model
  // for the robust optimum); here E carried at most 10 N and nothing from 6 ms after
  // touchdown, while B carried 520 N, and the walk failed as "leading tip lifts off the ground".
  EXPECT_EQ(w.steps_completed, 1) << w.failure;
  EXPECT_GT(e_least, 10.0);  // measured 30 N
  EXPECT_GT(e_most, 300.0);  // E carries the robot's weight (314 N) before B lets go
}

}  // namespace
}  // namespace gaitopt::sim
