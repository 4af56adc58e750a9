#include "ocp/solve/continuation.hpp"

#include <algorithm>
#include <utility>

#include <fmt/format.h>

#include "ocp/solve/gait_solve.hpp"

namespace gaitopt::ocp {
namespace {

/// A progress this close below 1 is 1: the steps' sum meets 1 up to rounding.
constexpr double kProgressEnd = 1e-9;

/// The options of a retry at initial barrier `mu`. Above the configured mu_init: the monotone
/// strategy, which starts at mu and lowers it from there, to re-centre an iterate pinned against
/// its bounds (the adaptive strategy chooses its first barrier itself: retries at mu_init 0.1 and
/// 1 from one iterate ended at the same point). Below it: a warm start (warmStarted), for a start
/// next to an optimum that a cold barrier pushes off it.
SolverOptions retryOptions(const SolverOptions& configured, double mu) {
  SolverOptions o = mu < configured.mu_init ? warmStarted(configured) : configured;
  if (mu >= configured.mu_init) o.mu_strategy = "monotone";
  o.mu_init = mu;
  return o;
}

/// Solves and records the stages of one continuation; sums their iterations and times.
class StageSolver {
 public:
  StageSolver(const OcpConfig& target, const std::function<void(const ContinuationStage&)>& report)
      : target_(target), report_(report) {}

  /// The stage of `config` at `progress` on `problem` from `start` (nullptr: the problem's
  /// initial guess), retried from its best iterate while it fails (ContinuationOptions).
  SolveResult solve(const GaitProblem& problem, const OcpConfig& config, double progress,
                    const SolverOptions& options, const WarmStart* start, const char* from) {
    SolveResult r = attempt(problem, config, progress, options, start, from);
    const ContinuationOptions& o = target_.continuation;
    for (int i = 0; i < o.retries && !r.success; ++i) {
      const double mu = o.retry_mu_init[std::min<size_t>(i, o.retry_mu_init.size() - 1)];
      const WarmStart best{r.best_iterate.x.size() > 0
                               ? r.best_iterate.x
                               : (start ? start->x : problem.nlp.initialGuess()),
                           {}};
      r = attempt(problem, config, progress, retryOptions(target_.solver, mu), &best,
                  "best iterate");
    }
    return r;
  }

  ContinuationResult result(GaitProblem problem, SolveResult last) {
    totals_.into(last);
    return {std::move(problem), std::move(last), std::move(stages_)};
  }

 private:
  SolveResult attempt(const GaitProblem& problem, const OcpConfig& config, double progress,
                      const SolverOptions& options, const WarmStart* start, const char* from) {
    SolveResult r = solveWithIpopt(problem.nlp, options, start);
    totals_.add(r);
    ContinuationStage s{progress,
                        pathParameters(config),
                        {},
                        from,
                        options.mu_init,
                        r.status,
                        r.success,
                        r.iterations,
                        r.cost,
                        r.max_violation,
                        r.wall_time_s};
    for (const Phase* phase : problem.phases()) s.segments.push_back(phase->layout.segments);
    stages_.push_back(s);
    if (target_.solver.progress)
      fmt::print(
          "continuation: progress {:.4f} from {} (mu_init {:g}): {} after {} iterations, "
          "cost {:.6g}\n",
          progress, from, options.mu_init, r.status, r.iterations, r.cost);
    if (report_) report_(s);
    return r;
  }

  const OcpConfig& target_;
  const std::function<void(const ContinuationStage&)>& report_;
  std::vector<ContinuationStage> stages_;
  SolveTotals totals_;
};

/// `config` with each free phase duration where the solution `x` of `problem` put it, so that
/// a problem built on another mesh starts there (as a refinement round does, gait_solve.cpp).
OcpConfig withSolvedDurations(OcpConfig config, const GaitProblem& problem,
                              const Eigen::VectorXd& x) {
  const auto phases = problem.phases();
  for (size_t i = 0; i < phases.size(); ++i)
    config.phases[i].duration = phases[i]->layout.durationAt(x);
  return config;
}

/// Whether `segments` equal segments per phase are the configured mesh already.
bool isConfiguredMesh(const OcpConfig& config, const std::vector<int>& segments) {
  for (size_t i = 0; i < config.phases.size(); ++i)
    if (config.phases[i].segments != segments[i] || !config.phases[i].fractions().empty())
      return false;
  return true;
}

/// The solved stage the path continues from.
struct Solved {
  GaitProblem problem;
  SolveResult result;
  double progress = 0;
};

}  // namespace

ContinuationResult solveByContinuation(
    const dynamics::Model& model, const OcpConfig& config, const gaits::Trajectory& guess,
    const std::function<void(const ContinuationStage&)>& on_stage) {
  const ContinuationOptions& o = config.continuation;
  StageSolver stages(config, on_stage);
  bool other_mesh = !o.mesh_segments.empty() && !isConfiguredMesh(config, o.mesh_segments);
  const auto onMesh = [&](OcpConfig c) {
    return other_mesh ? onSegments(std::move(c), o.mesh_segments) : c;
  };
  gaits::Trajectory base = guess;  // what each stage's problem is built from (x overrides it)
  // Without a parameter to move, the easy problem is the configured one: progress 1 at once.
  const double start = pathMoves(config) ? 0.0 : 1.0;
  OcpConfig easy = onMesh(configAt(config, start));
  Solved at{buildGaitProblem(model, easy, base), {}, start};
  at.result = stages.solve(at.problem, easy, start, config.solver, nullptr, "initial guess");
  double step = 1.0 / o.steps;
  int halvings = o.halvings;
  while (at.result.success) {
    if (other_mesh && at.progress >= o.mesh_until) {  // onto the configured mesh
      other_mesh = false;
      base = reconstructDense(at.problem, model, at.result.x, kRefinementResampleHz);
      const OcpConfig fine =
          withSolvedDurations(configAt(config, at.progress), at.problem, at.result.x);
      at.problem = buildGaitProblem(model, fine, base);
      at.result = stages.solve(at.problem, fine, at.progress, warmStarted(config.solver), nullptr,
                               "other mesh");
      continue;
    }
    if (at.progress >= 1) break;
    const double next = at.progress + step >= 1 - kProgressEnd ? 1.0 : at.progress + step;
    const OcpConfig c = onMesh(configAt(config, next));
    Solved tried{buildGaitProblem(model, c, base), {}, next};
    const WarmStart start{at.result.x, at.result.multipliers};
    tried.result =
        stages.solve(tried.problem, c, next, warmStarted(config.solver), &start, "previous stage");
    if (tried.result.success || halvings-- == 0) {
      at = std::move(tried);  // a success, or the failure the continuation gives up with
      continue;
    }
    step /= 2;
  }
  return stages.result(std::move(at.problem), std::move(at.result));
}

}  // namespace gaitopt::ocp
