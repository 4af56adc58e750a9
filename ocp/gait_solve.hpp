#pragma once
/// @file gait_solve.hpp
/// Solving the gait problem with mesh refinement (mesh_refinement.hpp): solve, estimate the
/// error of every segment, split those above the tolerance, re-solve warm-started from the
/// previous solution, until every segment is within tolerance or the rounds run out.
#include <functional>
#include <string>
#include <vector>

#include "ocp/gait_problem.hpp"
#include "ocp/ipopt_adapter.hpp"

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
};

/// A constraint row or variable bound of the gait problem, located on its time grid.
struct LocatedViolation {
  Violation violation;    ///< set or block name, its phase ("ssp", "dsp", or "link" for the
                          ///< touchdown, impact, periodicity, ...), index, amount, bounds
  std::string node_kind;  ///< "point" (collocation point), "segment", or "" (not on the grid)
  int node = -1;
  std::string part;  ///< what `index` counts: "row" (of a constraint) or "element" (of a point)
  int index = -1;    ///< the row or element within the node, -1 when not on the grid
};

/// The constraint row of `x` farthest outside its bounds.
LocatedViolation worstConstraint(const GaitProblem& problem, const Eigen::VectorXd& x);
/// The variable of `x` farthest outside its bounds.
LocatedViolation worstBound(const GaitProblem& problem, const Eigen::VectorXd& x);
/// One line for people, e.g. "ssp_clearance (ssp, point 12, row 0): -0.031 outside [0, inf]
/// by 0.031"; the index within the set or block when it is not on the grid.
std::string describe(const LocatedViolation& v);

/// Solves `config` from `guess`; refines while config.refinement.tolerance > 0. A failed round
/// ends the sequence (its result is returned). `on_round` sees each round as it finishes.
GaitSolution solveGait(const dynamics::Model& model, OcpConfig config,
                       const gaits::Trajectory& guess,
                       const std::function<void(const MeshRound&)>& on_round = {});

}  // namespace gaitopt::ocp
