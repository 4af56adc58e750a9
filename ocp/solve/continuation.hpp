#pragma once
/// @file continuation.hpp
/// Reaching a hard gait problem from an easy one (Allgower & Georg, "Introduction to Numerical
/// Continuation Methods", 2003, ch. 1: natural-parameter continuation). The easy problem is the
/// torque-squared problem on the configured mesh (continuation_path.hpp); the path then moves the
/// listed parameters (margins, strike velocity, cost weights) to their configured values in
/// ContinuationOptions::steps steps of progress, each stage started from the previous stage's
/// solution, primal and dual (Ipopt's warm_start_init_point with the multipliers).
///   - A stage Ipopt ends without success (iteration limit, restoration failure, local
///     infeasibility, ...) is retried from its best accepted iterate (BestIterate) at the initial
///     barriers retry_mu_init, at most `retries` times: one below the configured barrier warm,
///     for a start next to an optimum; the larger ones re-centre an iterate pinned against its
///     bounds (ContinuationOptions).
///   - A stage that still fails halves the step and is tried again from the last solved stage,
///     at most `halvings` times over the path; then the continuation gives up, with the failed
///     stage's result.
///   - Optionally the stages up to mesh_until are solved on another mesh (ContinuationOptions),
///     whose solution is then interpolated onto the configured mesh along the scheme's
///     polynomials and re-solved there, warm (warmStarted) from the primal point alone: the
///     multipliers do not carry over to other rows.
#include <functional>
#include <string>
#include <vector>

#include "dynamics/model.hpp"
#include "gaits/trajectory/trajectory.hpp"
#include "ocp/problem/gait_problem.hpp"
#include "ocp/solve/continuation_path.hpp"
#include "ocp/solve/ipopt_adapter.hpp"

namespace gaitopt::ocp {

/// One Ipopt solve on the path.
struct ContinuationStage {
  double progress = 0;
  PathParameters parameters;
  std::vector<int> segments;  ///< per phase
  /// Where it started: "initial guess", "previous stage" (primal-dual), "other mesh"
  /// (interpolated from the continuation's mesh), or "best iterate" (a retry)
  std::string start;
  double mu_init = 0;  ///< Ipopt's initial barrier
  std::string status;
  bool success = false;
  int iterations = 0;
  double cost = 0;
  double max_violation = 0;
  double wall_time_s = 0;
};

struct ContinuationResult {
  GaitProblem problem;  ///< of the last stage
  /// Of the last stage; iterations and times summed over all stages.
  SolveResult result;
  std::vector<ContinuationStage> stages;  ///< in the order solved, retries included
};

/// Solves `config` (its continuation options) from `guess` along the path. `on_stage` sees
/// each stage as it finishes.
ContinuationResult solveByContinuation(
    const dynamics::Model& model, const OcpConfig& config, const gaits::Trajectory& guess,
    const std::function<void(const ContinuationStage&)>& on_stage = {});

}  // namespace gaitopt::ocp
