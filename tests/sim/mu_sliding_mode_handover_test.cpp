// Mu's sliding-mode controller at the switch from single to double support (the "bumpless
// transfer" of mu_sliding_mode.hpp): the SSP low-passes its switching term into T_c, the
// correction it found for its model, and the DSP law adds it (the stance ankle's left out).
// Without it, with the controller's model off by Mu's case 3, the DSP started from T^ alone:
// the trailing tip was pressed with 826 N, 2.8 times the robot's weight, and the leading tip
// lifted off in step 1.
#include <gtest/gtest.h>

#include "dynamics/model_variation.hpp"
#include "five_link_gait.hpp"
#include "sim/controllers/mu_sliding_mode.hpp"
#include "sim/walk/hybrid_walk.hpp"
#include "support/shipped_export.hpp"

namespace gaitopt::sim {
namespace {

using gaits::Phase;

/// T_c: the last n = 5 entries of the memory, after the integral of (4.1).
Eigen::VectorXd carried(const Eigen::VectorXd& memory) {
  return memory.tail(5);
}

TEST(MuSlidingModeHandover, TheDoubleSupportAddsTheSingleSupportsTermButNotTheAnkles) {
  const auto& model = test::fiveLinkRobot();
  const Reference ref(test::polynomialGait(), model);
  const MuSlidingModeController c(model, muTable42(1), {0.2, 0.2, 0.05, 0.05});
  const gaits::Knot end = ref.at(Phase::kSsp, ref.touchdownTime() - 0.01);
  Eigen::VectorXd ssp_memory = Eigen::VectorXd::Zero(c.memorySize(Phase::kSsp));
  ASSERT_EQ(ssp_memory.size(), 10);
  ssp_memory.tail(5) << 7, -3, 2, 5, -11;  // T_c [N m]
  // On the reference the sliding variable is zero, tanh(gamma s) too: T_c relaxes to zero
  // at 1 / t_h (t_h = 0.05 s).
  const Eigen::VectorXd rate = c.memoryRate(Phase::kSsp, end.theta, end.dtheta, end, ssp_memory);
  EXPECT_LT((carried(rate) + ssp_memory.tail(5) / 0.05).norm(), 1e-9);

  const PhaseHandover handover{Phase::kSsp, end.theta, end.dtheta, end, ssp_memory};
  const gaits::Knot k = ref.at(Phase::kDsp, ref.touchdownTime());
  const Eigen::VectorXd dsp_memory =
      c.phaseStartMemory(Phase::kDsp, k.theta, k.dtheta, k, &handover);
  ASSERT_EQ(dsp_memory.size(), 8);
  Eigen::VectorXd want(5);
  want << 0, -3, 2, 5, -11;
  EXPECT_EQ(carried(dsp_memory), want);
  Eigen::VectorXd without = dsp_memory;
  without.tail(5).setZero();
  const VecD added = c.unclippedTorque(Phase::kDsp, k.theta, k.dtheta, k, dsp_memory) -
                     c.unclippedTorque(Phase::kDsp, k.theta, k.dtheta, k, without);
  EXPECT_LT((added - want).cwiseAbs().maxCoeff(), 1e-9);
  // No single support before (a step's start): nothing is carried.
  EXPECT_EQ(carried(c.phaseStartMemory(Phase::kDsp, k.theta, k.dtheta, k, nullptr)).norm(), 0.0);
}

// control() computes the SSP's switching term once for the torque and T_c's filter; it must
// give what torque() and memoryRate() give, in both phases, off the reference.
TEST(MuSlidingModeHandover, OneCallGivesTheTorqueAndTheMemoryRate) {
  const auto& model = test::fiveLinkRobot();
  const Reference ref(test::polynomialGait(), model);
  const auto errors = dynamics::muUncertaintyCase(2);
  const MuSlidingModeController c(dynamics::perturbedModel(model, errors), muTable42(2), errors);
  for (const Phase phase : {Phase::kSsp, Phase::kDsp}) {
    const gaits::Knot k = ref.at(phase, phase == Phase::kSsp ? 0.3 : ref.touchdownTime() + 0.02);
    const VecD theta = VecD(k.theta) + 0.01 * VecD::LinSpaced(5, -1, 1);
    const VecD dtheta = VecD(k.dtheta) - 0.2 * VecD::LinSpaced(5, -1, 1);
    const Eigen::VectorXd memory = Eigen::VectorXd::LinSpaced(c.memorySize(phase), -0.5, 3);
    const ControlOutput u = c.control(phase, theta, dtheta, k, memory);
    const VecD tau = c.torque(phase, theta, dtheta, k, memory);
    const Eigen::VectorXd rate = c.memoryRate(phase, theta, dtheta, k, memory);
    EXPECT_LT((u.tau - tau).cwiseAbs().maxCoeff(), 1e-12 * tau.cwiseAbs().maxCoeff());
    EXPECT_LT((u.memory_rate - rate).cwiseAbs().maxCoeff(), 1e-12 * rate.cwiseAbs().maxCoeff());
    if (phase == Phase::kSsp) {
      EXPECT_GT(carried(rate).norm(), 1.0);  // T_c's filter moves
    }
  }
}

// The robust optimum (configs/ocp/mu2004_walk_robust.yaml) with the controller's model off by
// Mu's case 3: without T_c the leading tip lifted off 4 ms into the first DSP (826 N on the
// trailing tip). Optimised builds only: the solve takes 4 s there.
TEST(MuSlidingModeHandover, TheRobustOptimumWalksMusCase3) {
#ifndef NDEBUG
  GTEST_SKIP() << "an OCP solve and a walk: optimised builds only";
#endif
  const gaitopt::test::ShippedExport robust = gaitopt::test::shippedExport("mu2004_walk_robust");
  ASSERT_TRUE(robust.success) << robust.status;
  const dynamics::Model& plant = robust.model;
  const Reference ref(robust.dense, plant);
  const auto errors = dynamics::muUncertaintyCase(3);
  const MuSlidingModeController c(dynamics::perturbedModel(plant, errors), muTable42(3), errors);
  double most_b = 0, least_e = 1e9;
  const double weight = plant.totalMass() * plant.gravity();
  const auto log = [&](const WalkSample& s) {
    if (s.step != 0 || s.phase != Phase::kDsp) return;
    most_b = std::max(most_b, s.force_stance(1));
    least_e = std::min(least_e, s.force_swing(1));
  };
  WalkOptions options;
  options.steps = 3;
  const WalkResult w = simulateWalk(plant, c, ref, options, log);
  RecordProperty("trailing_tip_most_N", std::to_string(most_b));
  RecordProperty("leading_tip_least_N", std::to_string(least_e));
  EXPECT_EQ(w.steps_completed, 3) << w.failure;
  EXPECT_LT(w.max_tracking_error, 0.01);
  EXPECT_LT(most_b, 2 * weight);  // 826 N = 2.8 weights without T_c
  EXPECT_GT(least_e, 0.0);
}

}  // namespace
}  // namespace gaitopt::sim
