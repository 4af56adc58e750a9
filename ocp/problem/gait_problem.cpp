#include "ocp/problem/gait_problem.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

#include "dynamics/dsp_dynamics.hpp"
#include "dynamics/ground.hpp"
#include "ocp/shape/gait_shape.hpp"
#include "ocp/shape/shape_builder.hpp"
#include "ocp/solve/dsp_chart_export.hpp"
#include "ocp/transcription/collocation_interpolation.hpp"

namespace gaitopt::ocp {

std::vector<const Phase*> GaitProblem::phasesOf(int step, int variant) const {
  std::vector<const Phase*> all;
  for (const BuiltPhase& b : built)
    if (b.step == step && b.variant == variant) all.push_back(&b.phase);
  if (all.empty())
    throw std::out_of_range("the problem has no step " + std::to_string(step + 1) + " of variant " +
                            std::to_string(variant));
  return all;
}

GaitProblem buildGaitProblem(const dynamics::Model& model, const OcpConfig& config,
                             const gaits::Trajectory& guess) {
  return assembleGaitProblem(describeGait(model, config), config, {guess});
}

namespace {

/// A knot from one point's variables (PointLayout).
gaits::Knot knotOf(const Eigen::VectorXd& v, const dynamics::Model& model, const Phase& phase,
                   double t) {
  const PointLayout& l = phase.point;
  gaits::Knot knot;
  knot.t = t;
  knot.phase = phase.kind;
  knot.theta = l.q.of(v);
  knot.dtheta = l.v.of(v);
  knot.ddtheta = l.a.of(v);
  knot.tau = l.u.of(v);
  if (l.hasContactForce()) knot.force_swing = l.lambda.of(v);
  knot.force_stance =
      dynamics::stanceForce<double>(model, knot.theta, knot.dtheta, knot.ddtheta, knot.force_swing);
  return knot;
}

void appendKnots(std::vector<gaits::Knot>& knots, const Phase& phase, const dynamics::Model& model,
                 const Eigen::VectorXd& x, double t0) {
  const PhaseLayout& l = phase.layout;
  for (int k = 0; k < l.points(); ++k)
    knots.push_back(knotOf(l.point(x, k), model, phase, t0 + l.time(k, l.durationAt(x))));
}

bool fullyActuated(const dynamics::Model& model) {
  return std::all_of(model.joints().begin(), model.joints().end(),
                     [](const auto& joint) { return joint.actuated; });
}

/// What a phase's export needs; a double support in reduced coordinates is exported on its
/// chart (dsp_chart_export.hpp).
struct PhaseExport {
  const Phase& phase;
  const Eigen::VectorXd& x;
  double step_length;
  std::optional<ChartTrack> chart;  ///< reduced coordinates only
};

/// An exported knot: the scheme's polynomials, with rates that are the derivatives of the
/// angles (exportPoint). A fully actuated robot gets the torques that produce this motion
/// exactly, Mu (2.43) in the SSP and (2.11) with the interpolated tip force in the DSP: the
/// scheme's own quadratic torques miss the dynamics between the points (by 3.2 N m, 8 % of the
/// peak torque, on the default optimum), which a controller's feed-forward would inherit. An
/// underactuated chain has no such torques; it keeps the scheme's, and summary.json reports
/// the residual.
gaits::Knot exportKnot(const PhaseExport& e, const dynamics::Model& model, double t, double t0) {
  const Phase& phase = e.phase;
  Eigen::VectorXd point = exportPoint(phase.layout, e.x, t);
  if (e.chart) placeOnChart(model, e.step_length, *e.chart, t, phase.point, point);
  gaits::Knot knot = knotOf(point, model, phase, t0 + t);
  if (!fullyActuated(model)) return knot;
  const VecD theta = knot.theta, dtheta = knot.dtheta, ddtheta = knot.ddtheta;
  knot.tau = phase.doubleSupport() ? dynamics::dspInverseDynamics(model, theta, dtheta, ddtheta,
                                                                  Vec2d(knot.force_swing))
                                   : dynamics::sspInverseDynamics(model, theta, dtheta, ddtheta);
  return knot;
}

/// Knots on the grid j / rate_hz inside the phase plus both ends (exportKnot); the grid is the
/// step's, not restarted at the phase start.
void appendDenseKnots(std::vector<gaits::Knot>& knots, const Phase& phase,
                      const dynamics::Model& model, const Eigen::VectorXd& x, double step_length,
                      double t0, double rate_hz) {
  const double total = phase.layout.durationAt(x);
  const double gap = 1e-3 / rate_hz;  // no sliver next to an end
  PhaseExport e{phase, x, step_length, std::nullopt};
  if (phase.reduced_coordinates) e.chart = chartTrack(model, phase, x);
  auto add = [&](double t) { knots.push_back(exportKnot(e, model, t, t0)); };
  add(0.0);
  for (auto j = static_cast<long>(std::floor(t0 * rate_hz)) + 1;; ++j) {
    const double t = static_cast<double>(j) / rate_hz - t0;
    if (t > total - gap) break;
    if (t <= gap) continue;
    add(t);
    // Exactly on the export grid (gaits/trajectory/grid_export.hpp), which then takes this knot as
    // it is rather than a quintic re-interpolation an ulp away from t0 + (j / rate - t0).
    knots.back().t = static_cast<double>(j) / rate_hz;
  }
  add(total);
}

/// The model of variant `variant`: the caller's for the nominal.
const dynamics::Model& modelOf(const GaitProblem& problem, const dynamics::Model& nominal,
                               int variant) {
  return variant == 0 ? nominal : *problem.models.at(static_cast<size_t>(variant));
}

}  // namespace

gaits::Trajectory reconstruct(const GaitProblem& problem, const dynamics::Model& model,
                              const Eigen::VectorXd& x, int step, int variant) {
  const dynamics::Model& m = modelOf(problem, model, variant);
  std::vector<gaits::Knot> knots;
  double t0 = 0;
  for (const Phase* phase : problem.phasesOf(step, variant)) {
    appendKnots(knots, *phase, m, x, t0);
    t0 += phase->layout.durationAt(x);
  }
  return gaits::Trajectory(m.name(), problem.stepLengthOf(variant), std::move(knots));
}

std::vector<gaits::Trajectory> reconstructSteps(const GaitProblem& problem,
                                                const dynamics::Model& model,
                                                const Eigen::VectorXd& x) {
  std::vector<gaits::Trajectory> steps;
  for (int step = 0; step < problem.steps; ++step)
    steps.push_back(reconstruct(problem, model, x, step));
  return steps;
}

gaits::Trajectory reconstructDense(const GaitProblem& problem, const dynamics::Model& model,
                                   const Eigen::VectorXd& x, double rate_hz, int step,
                                   int variant) {
  if (!(rate_hz > 0)) throw std::invalid_argument("the sample rate must be positive");
  const dynamics::Model& m = modelOf(problem, model, variant);
  std::vector<gaits::Knot> knots;
  double t0 = 0;
  for (const Phase* phase : problem.phasesOf(step, variant)) {
    appendDenseKnots(knots, *phase, m, x, problem.stepLengthOf(variant), t0, rate_hz);
    t0 += phase->layout.durationAt(x);
  }
  return gaits::Trajectory(m.name(), problem.stepLengthOf(variant), std::move(knots));
}

}  // namespace gaitopt::ocp
