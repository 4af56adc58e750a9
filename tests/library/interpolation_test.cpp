// A gait blended from a library against the gait solved at the same point: the five-link
// default problem at 0.5 m/s, blended from gaits solved 0.05 to 0.0125 m/s apart around it.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "dynamics/kinematics.hpp"
#include "gaits/export/consistency.hpp"
#include "gaits/export/export_checks.hpp"
#include "gaits/polynomial/retime.hpp"
#include "library/interpolation.hpp"
#include "library/point_problem.hpp"
#include "ocp/guess/initial_guess.hpp"
#include "ocp/solve/gait_solve.hpp"
#include "sim/controllers/reference.hpp"
#include "sim/scenario/scenario.hpp"
#include "sim/scenario/scenario_settings.hpp"

namespace gaitopt::library {
namespace {

TEST(Interpolation, CellWeightsBlendTheBracketingPoints) {
  const Grid grid({std::vector<double>{0.4, 0.5, 0.7}, {0.3, 0.4}, {0.0}});
  const auto w = cellWeights(grid, {0.55, 0.3, 0.0});
  ASSERT_EQ(w.size(), 2u);
  EXPECT_EQ(grid.point(w[0].first).name, "v0.500_L0.300_s+0.000");
  EXPECT_NEAR(w[0].second, 0.75, 1e-12);
  EXPECT_NEAR(w[1].second, 0.25, 1e-12);
  EXPECT_EQ(cellWeights(grid, {0.45, 0.35, 0.0}).size(), 4u);
  EXPECT_THROW(cellWeights(grid, {0.8, 0.35, 0.0}), std::domain_error);
  // A query at a grid value, to the last bit or not, is that point alone: a range's value
  // 0.3 + 0.6 and a typed 0.9 differ by 1e-16, which blended in a neighbour (a failed one
  // refused the point).
  const Grid range({std::vector<double>{0.3, 0.3 + 0.6, 1.5}, {0.2}, {0.0}});
  ASSERT_NE(range.axes()[0][1], 0.9);
  const auto at = cellWeights(range, {0.9, 0.2, 0.0});
  ASSERT_EQ(at.size(), 1u);
  EXPECT_EQ(at[0].first, 1);
  EXPECT_EQ(at[0].second, 1.0);
}

#ifdef NDEBUG  // five OCP solves: Release only
constexpr double kRate = 500;

/// The gait at `speed`, started as the library starts it: from the neighbour's gait, retimed
/// (null: from the polynomial gait).
gaits::Trajectory solveAt(const ocp::OcpConfig& base, double speed,
                          const gaits::Trajectory* neighbour, double rate_hz = kRate) {
  const PointProblem pp = pointProblem(base, {speed, base.step_length, 0.0});
  const gaits::Trajectory guess =
      neighbour ? gaits::retimed(*neighbour, phaseDurations(pp.config), base.step_length)
                : ocp::polynomialGuess(pp.model, pp.guess);
  const ocp::GaitSolution s = ocp::solveGait(pp.model, pp.config, guess);
  EXPECT_TRUE(s.result.success) << s.result.status;
  return ocp::reconstructDense(s.problem, pp.model, s.result.x, rate_hz);
}

double maxAngleError(const gaits::Trajectory& a, const gaits::Trajectory& b) {
  double worst = 0;
  for (const auto& k : a.knots()) {
    if (k.t > b.endTime()) continue;
    worst = std::max(worst, (k.theta - b.at(k.t).theta).cwiseAbs().maxCoeff());
  }
  return worst;
}

/// The largest distance of the swing tip from its touchdown point (step_length, 0) from the end
/// of the SSP on (the DSP pins it there) [m].
double maxTipMiss(const gaits::Trajectory& traj, const dynamics::Model& model) {
  const auto ssp_end = traj.phaseDurations().front().second + traj.startTime();
  double worst = 0;
  for (const auto& k : traj.knots()) {
    if (k.t < ssp_end) continue;
    const VecD theta = k.theta;
    const Vec2d tip = dynamics::pointPosition<double>(model.tipWeights(), theta);
    worst = std::max(worst, (tip - Vec2d(traj.stepLength(), 0)).norm());
  }
  return worst;
}

TEST(Interpolation, BlendErrorFallsWithTheSquareOfTheGridSpacing) {
  const ocp::OcpConfig base =
      ocp::loadOcpConfig(GAITOPT_SOURCE_DIR "/configs/ocp/mu2004_walk.yaml");
  const dynamics::Model model = ocp::problemModel(base);
  const double v = 0.5, length = base.step_length;
  const gaits::Trajectory direct = solveAt(base, v, nullptr);
  // The blend at the cell's midpoint misses a smooth family of gaits by h^2/8 f'' plus terms in
  // h^4, so halving the spacing h quarters the error. Measured orders log2(e(h) / e(h/2)): 2.01
  // from 0.05 to 0.025 m/s and 2.00 from 0.025 to 0.0125; from 0.1 to 0.05 it is 2.68, the
  // higher terms still large, so the coarsest spacing is 0.05.
  const std::vector<double> spacings{0.05, 0.025, 0.0125};
  std::vector<double> errors;
  for (const double h : spacings) {
    const gaits::Trajectory slow = solveAt(base, v - h / 2, &direct);
    const gaits::Trajectory fast = solveAt(base, v + h / 2, &direct);
    const Grid grid({std::vector<double>{v - h / 2, v + h / 2}, {length}, {0.0}});
    const GaitLookup lookup = [&](int p) { return p == 0 ? &slow : &fast; };
    const gaits::Trajectory blend = interpolateGait(grid, lookup, model, {v, length, 0.0}, kRate);
    EXPECT_NEAR(blend.duration(), length / v, 1e-12);
    // Relabelling is linear, so a blend of periodic gaits is periodic.
    EXPECT_LT(gaits::periodicityError(blend, model), 1e-9);
    errors.push_back(maxAngleError(blend, direct));
    const double miss = maxTipMiss(blend, model), corner_miss = maxTipMiss(slow, model);
    std::printf(
        "blend at %.2f m/s from %.4f/%.4f: max angle error %.4g rad; DSP tip off its "
        "point by %.3g m (solved corner %.3g m)\n",
        v, v - h / 2, v + h / 2, errors.back(), miss, corner_miss);
    // The blend is put back on its contacts (contact_projection.hpp): blended angles alone left
    // the tip 0.05 to 1.1 mm off its point and the swing tip landing above the ground.
    EXPECT_LT(miss, 1e-9);
    EXPECT_LT(gaits::maxDspTipDrift(blend, model), 1e-9);
  }
  EXPECT_GT(errors.back(), 1e-5);  // a blend is not the solution
  for (size_t i = 0; i + 1 < errors.size(); ++i)
    EXPECT_NEAR(std::log2(errors[i] / errors[i + 1]), 2.0, 0.1)
        << "observed order from the spacing " << spacings[i] << " m/s to " << spacings[i + 1];
}

// What the projection is for: the blend at 0.5 m/s of the optima at 0.45 and 0.55 m/s walks 20
// steps on the rigid ground under the law that feeds the plan's double support forward (blended
// angles alone fell in the first touchdown).
TEST(Interpolation, ABlendOnItsContactsWalksUnderThePlansDoubleSupport) {
  const ocp::OcpConfig base =
      ocp::loadOcpConfig(GAITOPT_SOURCE_DIR "/configs/ocp/mu2004_walk.yaml");
  const dynamics::Model model = ocp::problemModel(base);
  const double v = 0.5, length = base.step_length;
  const gaits::Trajectory direct = solveAt(base, v, nullptr, 1000);
  const gaits::Trajectory slow = solveAt(base, 0.45, &direct, 1000);
  const gaits::Trajectory fast = solveAt(base, 0.55, &direct, 1000);
  const Grid grid({std::vector<double>{0.45, 0.55}, {length}, {0.0}});
  const GaitLookup lookup = [&](int p) { return p == 0 ? &slow : &fast; };
  const gaits::Trajectory blend = interpolateGait(grid, lookup, model, {v, length, 0.0}, 1000);
  sim::ScenarioSettings settings;
  settings.controller = "computed_torque_plan_dsp";
  const sim::WalkResult w =
      sim::runScenario(model, sim::Reference(blend, model), sim::makeScenario(settings)).walk;
  RecordProperty("steps", w.steps_completed);
  EXPECT_EQ(w.steps_completed, 20) << w.failure;
}
#endif

}  // namespace
}  // namespace gaitopt::library
