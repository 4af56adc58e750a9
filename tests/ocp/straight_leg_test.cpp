// Gait optimisation for the robots with straight legs: the straight-leg initial
// guess (ocp/guess/straight_leg_guess.hpp) meets its boundary conditions, and the shipped configs
// of the compass gait and the three-link walker solve to periodic gaits that an independent
// re-simulation (RKF 7(8), ocp/solve/resimulation.hpp) and the closed-form impact map
// (Mu 2.32-2.36) reproduce. configs/ocp/compass_gait_passive.yaml is the known answer: on a slope
// the compass gait walks with no torque at all (McGeer 1990; Goswami et al. 1998), so the
// torque-squared optimum must be zero, and the zero-torque motion from its start state must repeat
// itself.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "dynamics/impact/impact.hpp"
#include "dynamics/impact/relabel.hpp"
#include "dynamics/kinematics.hpp"
#include "dynamics/robot_files/robot_config.hpp"
#include "ocp/guess/initial_guess.hpp"
#include "ocp/guess/straight_leg_guess.hpp"
#include "ocp/solve/gait_solve.hpp"
#include "ocp/solve/resimulation.hpp"

namespace gaitopt::ocp {
namespace {

OcpConfig shipped(const std::string& name) {
  return loadOcpConfig(std::string(GAITOPT_SOURCE_DIR) + "/configs/ocp/" + name + ".yaml");
}

/// The start state of the next step from a strike state: single impact (closed form, not the
/// OCP's impulse variables), then relabelling (Mu 2.38).
ChainState nextStart(const dynamics::Model& model, const ChainState& strike) {
  const dynamics::ImpactResult r = dynamics::singleImpact(model, strike.first, strike.second);
  return {dynamics::relabelAngles<double>(model, strike.first),
          dynamics::relabelRates<double>(r.dtheta_plus)};
}

class StraightLegGuess : public ::testing::TestWithParam<std::string> {};

TEST_P(StraightLegGuess, RunsFromTheRelabelledTouchdownPostureToIt) {
  const OcpConfig c = shipped(GetParam());
  const dynamics::Model model = problemModel(c);
  const gaits::Trajectory guess = initialGuess(model, c);
  const VecD start = guess.knots().front().theta, end = guess.knots().back().theta;
  EXPECT_NEAR(guess.endTime(), c.phases.front().duration, 1e-12);
  // Touchdown: the swing tip on the ground one step ahead, the hip above the middle.
  const Vec2d tip = dynamics::swingTip<double>(model, end);
  EXPECT_NEAR(tip.x(), c.step_length, 1e-12);
  EXPECT_NEAR(tip.y(), 0.0, 1e-12);
  EXPECT_NEAR(dynamics::pointPosition<double>(model.hipWeights(), end).x(), c.step_length / 2,
              1e-12);
  // The start is the touchdown posture with the legs swapped: stance tip at B, swing tip one
  // step behind, and relabelling the start gives the touchdown posture back (an involution).
  EXPECT_NEAR(dynamics::swingTip<double>(model, start).x(), -c.step_length, 1e-12);
  EXPECT_LT((dynamics::relabelAngles<double>(model, start) - end).cwiseAbs().maxCoeff(), 1e-12);
  // Every knot satisfies the SSP dynamics with its torques (Mu 2.43).
  for (const gaits::Knot& k : guess.knots()) {
    const VecD tau = dynamics::sspInverseDynamics(model, k.theta, k.dtheta, k.ddtheta);
    ASSERT_LT((tau - k.tau).cwiseAbs().maxCoeff(), 1e-9) << "t = " << k.t;
  }
}

INSTANTIATE_TEST_SUITE_P(Robots, StraightLegGuess,
                         ::testing::Values("compass_gait_walk", "three_link_walk",
                                           "compass_gait_passive"));

TEST(StraightLegGuessInput, KneesAndDoubleSupportAreRefused) {
  OcpConfig c = shipped("compass_gait_walk");
  const dynamics::Model five = dynamics::loadRobot(std::string(GAITOPT_SOURCE_DIR) +
                                                   "/configs/robots/mu2004_five_link.yaml");
  EXPECT_THROW(straightLegGuess(five, c), std::invalid_argument);
  c.phases.push_back({"DSP", 0.1, 0, 0, 4, {}});
  EXPECT_THROW(straightLegGuess(problemModel(c), c), std::invalid_argument);
}

struct StraightLegSolve {
  dynamics::Model model;
  GaitSolution solution;
};

StraightLegSolve solveShipped(const std::string& name) {
  const OcpConfig c = shipped(name);
  dynamics::Model model = problemModel(c);
  GaitSolution s = solveGait(model, c, initialGuess(model, c));
  return {std::move(model), std::move(s)};
}

class ShippedStraightLegConfig : public ::testing::TestWithParam<std::string> {
 protected:
  void SetUp() override {
#ifndef NDEBUG
    GTEST_SKIP() << "a solve and a re-simulation: optimised builds only";
#endif
  }
};

TEST_P(ShippedStraightLegConfig, SolvesToAPeriodicGaitTheResimulationReproduces) {
  const StraightLegSolve s = solveShipped(GetParam());
  const SolveResult& r = s.solution.result;
  const GaitProblem& p = s.solution.problem;
  ASSERT_TRUE(r.success) << r.status;
  const int last = p.ssp.layout.points() - 1;
  // Periodic through the closed-form impact map and relabelling, not the OCP's own rows.
  const ChainState next = nextStart(s.model, sspPointState(p, r.x, last));
  const StateError period = difference(next, sspPointState(p, r.x, 0));
  EXPECT_LT(period.angle, 1e-7);
  EXPECT_LT(period.rate, 1e-6);
  // The torques re-simulated segment by segment reproduce each segment's end state (local
  // error, Hermite-Simpson O(h^5)); open loop over the whole SSP the unstable single support
  // (the three-link walker's torso above an unactuated ankle) amplifies it.
  const StateError local = sspSegmentError(p, s.model, r.x);
  const StateError sim = sspEndStateError(p, s.model, r.x);
  RecordProperty("cost", fmt::format("{:.6g}", r.cost));
  RecordProperty("segment_error", fmt::format("{:.2e} {:.2e}", local.angle, local.rate));
  RecordProperty("end_error", fmt::format("{:.2e} {:.2e}", sim.angle, sim.rate));
  EXPECT_LT(local.angle, 1e-5);
  EXPECT_LT(local.rate, 1e-4);
  EXPECT_LT(sim.angle, 1e-3);
  EXPECT_LT(sim.rate, 1e-2);
}

INSTANTIATE_TEST_SUITE_P(Robots, ShippedStraightLegConfig,
                         ::testing::Values("compass_gait_walk", "three_link_walk"));

class PassiveSlopeWalk : public ShippedStraightLegConfig {};

TEST_F(PassiveSlopeWalk, NeedsNoTorqueAndRepeatsItselfWithout) {
  const StraightLegSolve s = solveShipped("compass_gait_passive");
  const SolveResult& r = s.solution.result;
  const GaitProblem& p = s.solution.problem;
  ASSERT_TRUE(r.success) << r.status;
  double peak = 0;
  for (int k = 0; k < p.ssp.layout.points(); ++k)
    peak = std::max(peak, p.ssp.point.u.of(p.ssp.layout.point(r.x, k)).cwiseAbs().maxCoeff());
  RecordProperty("cost", fmt::format("{:.3e}", r.cost));
  RecordProperty("peak_hip_torque_Nm", fmt::format("{:.3e}", peak));
  EXPECT_LT(r.cost, 1e-8);  // N^2 m^2 s; a level-ground step costs ~10^2 (compass_gait_walk)
  EXPECT_LT(peak, 1e-4);    // N m
  // Independently: the zero-torque motion from the optimum's start state, integrated by RKF
  // 7(8) over the optimum's step, ends with the swing tip on the ground one step ahead, and
  // the impact map and relabelling bring it back to where it started: a passive gait.
  const double duration = p.ssp.layout.durationAt(r.x);
  const ChainState start = sspPointState(p, r.x, 0);
  ChainState strike = start;
  simulateSsp(
      s.model, start.first, start.second, [](double) { return VecD(VecD::Zero(2)); },
      {0.0, duration}, 1e-12,
      [&](double t, const VecD& theta, const VecD& dtheta) {
        if (t > 0) strike = {theta, dtheta};
      });
  const Vec2d tip = dynamics::swingTip<double>(s.model, strike.first);
  EXPECT_NEAR(tip.x(), p.step_length, 1e-6);
  EXPECT_NEAR(tip.y(), 0.0, 1e-6);
  const StateError period = difference(nextStart(s.model, strike), start);
  RecordProperty("zero_torque_period_error",
                 fmt::format("{:.2e} {:.2e}", period.angle, period.rate));
  EXPECT_LT(period.angle, 1e-6);
  EXPECT_LT(period.rate, 1e-5);
}

}  // namespace
}  // namespace gaitopt::ocp
