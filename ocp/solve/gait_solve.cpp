#include "ocp/solve/gait_solve.hpp"

#include <algorithm>

#include "ocp/solve/dsp_chart_export.hpp"
#include "ocp/transcription/biped_dynamics.hpp"
#include "ocp/transcription/collocation_interpolation.hpp"
#include "ocp/transcription/mesh_refinement.hpp"

namespace gaitopt::ocp {
namespace {

MeshRound roundOf(const GaitProblem& p, const SolveResult& r, const std::vector<double>& errors) {
  MeshRound round{{}, r.status, r.iterations, r.cost, 0, r.wall_time_s};
  for (const Phase* phase : p.phases()) round.segments.push_back(phase->layout.segments);
  for (double e : errors) round.max_segment_error = std::max(round.max_segment_error, e);
  return round;
}

/// Refines every phase of `config` from the errors of the solution; false if nothing to split.
bool refine(OcpConfig& config, const GaitProblem& p, const SolveResult& r,
            const std::vector<Eigen::VectorXd>& errors) {
  bool changed = false;
  const auto phases = p.phases();
  for (size_t i = 0; i < phases.size(); ++i) {
    const PhaseLayout& l = phases[i]->layout;
    PhaseConfig& phase = config.phases[i];
    phase.clearMesh();
    phase.mesh = refinedMesh(l, errors[i], config.refinement.tolerance);
    changed = changed || static_cast<int>(phase.mesh.size()) - 1 != l.segments;
    phase.segments = static_cast<int>(phase.mesh.size()) - 1;
    phase.duration = l.durationAt(r.x);  // a free duration restarts where it ended
  }
  return changed;
}

/// The error estimate of a phase (mesh_refinement.hpp) along the polynomials its export follows:
/// a double support in reduced coordinates is read on its chart, where its tip stays pinned.
Eigen::VectorXd phaseErrors(const GaitProblem& p, const Phase& phase, const dynamics::Model& model,
                            const Eigen::VectorXd& x) {
  const BipedDynamics dynamics(model, phase.point);
  if (!phase.reduced_coordinates) return segmentErrors(phase.layout, dynamics, x);
  const ChartTrack track = chartTrack(model, phase, x);
  return segmentErrors(phase.layout, dynamics, phase.layout.durationAt(x), [&](double t) {
    Eigen::VectorXd point = interpolatePoint(phase.layout, x, t);
    placeOnChart(model, p.step_length, track, t, phase.point, point);
    return point;
  });
}

/// The first round: a solve from `guess`, or the continuation the config asks for.
GaitSolution firstRound(const dynamics::Model& model, const OcpConfig& config,
                        const gaits::Trajectory& guess) {
  if (config.continuation.enabled) {
    ContinuationResult c = solveByContinuation(model, config, guess);
    return {std::move(c.problem), std::move(c.result), {}, std::move(c.stages)};
  }
  GaitSolution s{buildGaitProblem(model, config, guess), {}, {}, {}};
  s.result = solveWithIpopt(s.problem.nlp, config.solver);
  return s;
}

}  // namespace

GaitSolution solveGait(const dynamics::Model& model, OcpConfig config,
                       const gaits::Trajectory& guess,
                       const std::function<void(const MeshRound&)>& on_round) {
  GaitSolution s = firstRound(model, config, guess);
  SolveTotals totals;
  for (int round = 0;; ++round) {
    if (round > 0) s.result = solveWithIpopt(s.problem.nlp, warmStarted(config.solver));
    totals.add(s.result);
    std::vector<Eigen::VectorXd> errors;
    std::vector<double> all;
    for (const Phase* phase : s.problem.phases()) {
      errors.push_back(phaseErrors(s.problem, *phase, model, s.result.x));
      all.insert(all.end(), errors.back().begin(), errors.back().end());
    }
    s.history.push_back(roundOf(s.problem, s.result, all));
    if (on_round) on_round(s.history.back());
    const bool done = !s.result.success || config.refinement.tolerance <= 0 ||
                      round == config.refinement.max_rounds ||
                      !refine(config, s.problem, s.result, errors);
    if (done) break;
    s.problem = buildGaitProblem(
        model, config, reconstructDense(s.problem, model, s.result.x, kRefinementResampleHz));
  }
  totals.into(s.result);
  return s;
}

}  // namespace gaitopt::ocp
