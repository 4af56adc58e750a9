#pragma once
/// @file continuation_options.hpp
/// The `continuation:` section of an OCP config (docs/optimal_gaits.md#continuation): how a hard
/// problem is reached from the torque-squared problem on its mesh (continuation.hpp).
#include <string>
#include <vector>

#include "config/yaml_reader.hpp"

namespace gaitopt::ocp {

struct ContinuationOptions {
  bool enabled = false;
  /// Stages from the easy problem (progress 0) to the configured one (progress 1), in equal
  /// steps of progress
  int steps = 4;
  /// Parameters whose easy and configured values are both positive (the cost weights) move
  /// geometrically with progress, so each step multiplies them by the same factor; false, or
  /// a zero end (the margins start at 0): linearly.
  bool geometric = true;
  /// The easy problem's weight of every cost term but torque squared, as a fraction of its
  /// configured weight: small enough that torque squared dominates, positive so that the work
  /// slacks stay bounded (a zero weight leaves s+ = s- + p free to grow under the barrier).
  double cost_start = 1e-4;
  /// The parameter groups that start easy (continuation_path.hpp): "margins" (friction and
  /// ZMP), "strike" (the strike's least normal velocity), "cost" (the weights but torque
  /// squared). The strike is not moved unless asked: a rigid impact's impulses scale with the
  /// strike velocity, so their friction cones bound its direction alone at any velocity above 0
  /// and none at 0; the problems at 0 and just above it differ by a finite step (measured on
  /// mu2004_walk_robust.yaml at its margins: a step of the least velocity from 0 to 1.25 mm/s
  /// stopped at the iteration limit, and so did its restarts at barriers 0.1 and 1). The others
  /// keep their configured values on the whole path; with none (config `parameters: none`) the
  /// path is the mesh continuation alone.
  std::vector<std::string> parameters = {"margins", "cost"};
  /// The groups one after another, in the order listed, each over an equal share of the
  /// progress (groups the config does not move take none); false: all together.
  bool sequential = false;
  /// How often a failed stage's step is halved before the continuation gives up.
  int halvings = 3;
  /// Restarts of a stage Ipopt ends without success, each from the best accepted iterate
  /// (BestIterate) at initial barrier retry_mu_init[i] (the last one repeats): below the
  /// configured mu_init a warm start (warmStarted), for a start next to an optimum that the
  /// configured barrier pushed away; above it the monotone barrier strategy from that barrier,
  /// which re-centres an iterate pinned against its bounds. Measured on mu2004_walk_robust.yaml
  /// started from its own optimum on another mesh: the configured barrier stopped at 500
  /// iterations on all 5 meshes, and so did the restarts at 0.1 and 1; the warm restart
  /// converged on all 5 in 9 to 20 iterations.
  int retries = 3;
  std::vector<double> retry_mu_init = {1e-5, 0.1, 1.0};
  /// Mesh continuation: segments per phase (SSP, then DSP) of another mesh (empty: off), e.g. a
  /// coarser one, or the one a problem is known to solve on. The stages of progress <=
  /// mesh_until are solved on it, then its solution is interpolated onto the configured mesh
  /// (the scheme's polynomials, reconstructDense) and re-solved there, and the path goes on.
  std::vector<int> mesh_segments;
  double mesh_until = 0;
};

/// The section under `r`; cross-checks with the phases and costs are the caller's.
/// @throws config::ConfigError naming the key.
ContinuationOptions readContinuation(const config::YamlReader& r);

}  // namespace gaitopt::ocp
