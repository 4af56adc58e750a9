#pragma once
/// @file gait_solve.hpp
/// Solving the gait problem with mesh refinement (mesh_refinement.hpp): solve, estimate the
/// error of every segment, split those above the tolerance, re-solve warm-started from the
/// previous solution, until every segment is within tolerance or the rounds run out. With a
/// `continuation:` section the first round is reached by continuation (continuation.hpp).
#include <functional>
#include <string>
#include <vector>

#include "ocp/problem/gait_problem.hpp"
#include "ocp/solve/continuation.hpp"
#include "ocp/solve/ipopt_adapter.hpp"

namespace gaitopt::ocp {

/// The rate at which a refined round resamples the previous round's solution into its initial
/// guess [Hz]: far finer than any mesh (a 0.7 s step on 100 segments has ~7 ms segments), so
/// the guess is the previous solution's own polynomials.
inline constexpr double kRefinementResampleHz = 2000;

/// One solve of the refinement sequence.
struct MeshRound {
  std::vector<int> segments;  ///< per phase (SSP, then DSP)
  std::string status;
  int iterations = 0;
  double cost = 0;
  double max_segment_error = 0;  ///< max eta_k over all phases [N m s]
  double wall_time_s = 0;
};

struct GaitSolution {
  GaitProblem problem;  ///< of the last round
  SolveResult result;   ///< of the last round; iterations and times summed over rounds
  std::vector<MeshRound> history;
  /// The path of the first round when the config asks for a continuation (else empty).
  std::vector<ContinuationStage> continuation;
};

/// Solves `config` from `guess`; refines while config.refinement.tolerance > 0. A failed round
/// ends the sequence (its result is returned). `on_round` sees each round as it finishes; the
/// first round's iterations and time are those of its whole continuation.
GaitSolution solveGait(const dynamics::Model& model, OcpConfig config,
                       const gaits::Trajectory& guess,
                       const std::function<void(const MeshRound&)>& on_round = {});

}  // namespace gaitopt::ocp
