#include "ocp/gait_solve.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "ocp/biped_dynamics.hpp"
#include "ocp/mesh_refinement.hpp"

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
    phase.mesh = refinedMesh(l, errors[i], config.refinement.tolerance);
    changed = changed || static_cast<int>(phase.mesh.size()) - 1 != l.segments;
    phase.segments = static_cast<int>(phase.mesh.size()) - 1;
    phase.duration = l.durationAt(r.x);  // a free duration restarts where it ended
  }
  return changed;
}

}  // namespace

LocatedViolation worstConstraint(const GaitProblem& problem, const Eigen::VectorXd& x) {
  LocatedViolation v{problem.nlp.worstConstraint(x), "", -1, "row", -1};
  for (const auto& set : problem.nlp.constraintSets()) {
    if (set->name() != v.violation.name) continue;
    const NodeOfRow node = set->nodeOf(v.violation.index);
    v.node_kind = node.kind;
    v.node = node.index;
    v.index = node.row;
  }
  return v;
}

LocatedViolation worstBound(const GaitProblem& problem, const Eigen::VectorXd& x) {
  LocatedViolation v{problem.nlp.worstBound(x), "", -1, "element", -1};
  const auto& blocks = problem.nlp.variableBlocks();
  const auto block = std::find_if(blocks.begin(), blocks.end(), [&](const VariableBlock& b) {
    return b.name == v.violation.name;
  });
  for (const Phase* phase : problem.phases()) {
    const PhaseLayout* l = &phase->layout;
    if (block == blocks.end() || block->offset != l->offset) continue;  // not a phase's points
    v.node_kind = "point";
    v.node = v.violation.index / l->pointSize();
    v.index = v.violation.index % l->pointSize();
  }
  return v;
}

std::string describe(const LocatedViolation& v) {
  const Violation& w = v.violation;
  if (w.name.empty()) return "none";
  const std::string where =
      v.node < 0 ? fmt::format("{}, {} {}", w.phase, v.part, w.index)
                 : fmt::format("{}, {} {}, {} {}", w.phase, v.node_kind, v.node, v.part, v.index);
  return fmt::format("{} ({}): {:.4g} outside [{:.4g}, {:.4g}] by {:.3g}", w.name, where, w.value,
                     w.lower, w.upper, w.amount);
}

GaitSolution solveGait(const dynamics::Model& model, OcpConfig config,
                       const gaits::Trajectory& guess,
                       const std::function<void(const MeshRound&)>& on_round) {
  GaitSolution s{buildGaitProblem(model, config, guess), {}, {}};
  SolverOptions options = config.solver;
  double wall = 0, callbacks = 0;
  int iterations = 0;
  for (int round = 0;; ++round) {
    s.result = solveWithIpopt(s.problem.nlp, options);
    wall += s.result.wall_time_s;
    callbacks += s.result.callback_time_s;
    iterations += s.result.iterations;
    std::vector<Eigen::VectorXd> errors;
    std::vector<double> all;
    for (const Phase* phase : s.problem.phases()) {
      errors.push_back(
          segmentErrors(phase->layout, BipedDynamics(model, phase->point), s.result.x));
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
    options = warmStarted(config.solver);
  }
  s.result.wall_time_s = wall;
  s.result.callback_time_s = callbacks;
  s.result.iterations = iterations;
  return s;
}

}  // namespace gaitopt::ocp
