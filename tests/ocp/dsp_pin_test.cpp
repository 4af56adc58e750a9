// The double-support tip pinned at position level (ocp/dsp_pin.hpp, after Posa et al. 2016):
// the whole NLP keeps exact derivatives with the pin, the pin takes the place of the rows it
// makes redundant, and the default problem's dense export holds E at (step_length, 0), checked
// on the export by gaits::maxDspTipDrift, where the acceleration-level pin alone lets it drift.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include "dynamics/robot_config.hpp"
#include "gaits/export_checks.hpp"
#include "ocp/gait_problem.hpp"
#include "ocp/initial_guess.hpp"
#include "ocp/ipopt_adapter.hpp"
#include "support/nlp_derivatives.hpp"

namespace gaitopt::ocp {
namespace {

const std::string kConfig = std::string(GAITOPT_SOURCE_DIR) + "/configs/ocp/mu2004_walk.yaml";

TEST(DspPin, WholeNlpJacobianAndHessianEqualCentralDifferences) {
  auto c = loadOcpConfig(kConfig);
  c.dsp_position_pin = true;
  c.phases.front().segments = 2;  // small: every column is differenced
  c.phases.back().segments = 2;   // two segments: a pin inside the phase and one at its end
  const auto model = dynamics::loadRobot(c.robot_path);
  const GaitProblem p = buildGaitProblem(model, c, polynomialGuess(model, c));
  ASSERT_TRUE(p.dsp->position_pinned);
  const test::DerivativeErrors e = test::compareWithCentralDifferences(p.nlp, 0.02);
  EXPECT_LT(e.jacobian, 1e-6);
  EXPECT_LT(e.hessian, 1e-6);
}

TEST(DspPin, ReplacesTheAccelerationRowsOneForOne) {
  // Per segment: 4 pin rows in, the 2 + 2 acceleration rows of the midpoint and the end out,
  // so the NLP keeps its size in rows (square dynamics), plus none in variables.
  auto c = loadOcpConfig(kConfig);
  c.dsp_position_pin = true;
  const auto model = dynamics::loadRobot(c.robot_path);
  const GaitProblem pinned = buildGaitProblem(model, c, polynomialGuess(model, c));
  c.dsp_position_pin = false;
  const GaitProblem loose = buildGaitProblem(model, c, polynomialGuess(model, c));
  ASSERT_FALSE(loose.dsp->position_pinned);
  EXPECT_EQ(pinned.nlp.constraints(), loose.nlp.constraints());
  EXPECT_EQ(pinned.nlp.variables(), loose.nlp.variables());
  // The trapezoid has one free tip force per segment for four rows: it keeps the acceleration pin.
  c.dsp_position_pin = true;
  c.scheme = Scheme::kTrapezoidal;
  EXPECT_FALSE(buildGaitProblem(model, c, polynomialGuess(model, c)).dsp->position_pinned);
}

/// The default problem solved with the pin at position level (or not), and its export.
struct PinnedSolve {
  GaitProblem problem;
  SolveResult result;
};

PinnedSolve solveDefault(const dynamics::Model& model, bool position_pin) {
  auto c = loadOcpConfig(kConfig);
  c.dsp_position_pin = position_pin;
  PinnedSolve s{buildGaitProblem(model, c, polynomialGuess(model, c)), {}};
  s.result = solveWithIpopt(s.problem.nlp, c.solver);
  return s;
}

TEST(DspPin, DefaultOptimumsDenseExportHoldsTheTipAtTheNodesAndBetweenThem) {
  const auto model = dynamics::loadRobot(loadOcpConfig(kConfig).robot_path);
  const PinnedSolve pinned = solveDefault(model, true);
  ASSERT_TRUE(pinned.result.success) << pinned.result.status;
  const PhaseLayout& dsp = pinned.problem.dsp->layout;
  // Sampled at segments / T_D the DSP's samples are its nodes (the SSP's 0.6 s is a multiple).
  const double node_rate = dsp.segments / dsp.duration;
  const double at_nodes = gaits::maxDspTipDrift(
      reconstructDense(pinned.problem, model, pinned.result.x, node_rate), model);
  const double between = gaits::maxDspTipDrift(
      reconstructDense(pinned.problem, model, pinned.result.x, 1000.0), model);
  RecordProperty("drift_at_nodes_m", fmt::format("{:.2e}", at_nodes));
  RecordProperty("drift_between_nodes_m", fmt::format("{:.2e}", between));
  EXPECT_LT(at_nodes, 1e-6);
  EXPECT_LT(between, 1e-4);

  // The acceleration-level pin alone misses both bounds: the test tells the two apart.
  const PinnedSolve loose = solveDefault(model, false);
  ASSERT_TRUE(loose.result.success) << loose.result.status;
  EXPECT_GT(
      gaits::maxDspTipDrift(reconstructDense(loose.problem, model, loose.result.x, 1000.0), model),
      1e-4);
}

}  // namespace
}  // namespace gaitopt::ocp
