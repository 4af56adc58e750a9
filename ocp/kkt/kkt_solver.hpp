#pragma once
/// @file kkt_solver.hpp
/// Ipopt's augmented system solved by BlockLdl with pairs from kkt_pairs.hpp: what Pardiso's
/// phases 11 (analyse), 22 (factorize) and 33 (solve) do for Ipopt (pardiso_interface.cpp).
/// Why not MUMPS: on these problems (4 000 rows, 26 000 entries) MUMPS spends 3.7 ms on a
/// factorization of 2.7 Mflop, its bookkeeping per front rather than arithmetic, and two thirds
/// of a whole solve (results/solve_profile.md); Debian ships no other solver Ipopt can load.
/// What static pivots cost: no pivoting inside the elimination, so a matrix whose pairs leave a
/// zero pivot (clamped and reported) or a small one (digits lost) is solved less accurately than
/// by MUMPS; on three shipped configs Ipopt then takes another path or does not converge
/// (results/linear_solver_compare.csv), which is why `ldl` is an option and not the default.
#include <memory>
#include <vector>

#include "ocp/kkt/block_ldl.hpp"
#include "ocp/kkt/symmetric_pattern.hpp"

namespace gaitopt::ocp::kkt {

class KktSolver {
 public:
  explicit KktSolver(SymmetricPattern pattern);

  /// Pairs the rows by these values and orders the blocks.
  void analyse(const double* values);
  /// Factorizes A(values); analyses again first if a variable row's diagonal has become zero
  /// since (Ipopt's first matrix, for the least-squares multipliers, has an identity there).
  void factorize(const double* values);
  /// rhs := A^{-1} rhs, then up to `refinementSteps` steps of iterative refinement against
  /// A(values); returns the steps taken.
  int solve(const double* values, double* rhs, int refinementSteps) const;

  int negativeEigenvalues() const { return ldl_->negativeEigenvalues(); }
  int perturbedPivots() const { return ldl_->perturbedPivots(); }
  int analyses() const { return analyses_; }

 private:
  bool lostADiagonal(const double* values) const;

  SymmetricPattern pattern_;
  int constraintStart_;
  std::vector<char> mustPair_;  // row -> a variable row seen with a zero diagonal
  std::vector<char> paired_;    // row -> in a 2x2 pivot
  std::unique_ptr<BlockLdl> ldl_;
  int analyses_ = 0;
};

}  // namespace gaitopt::ocp::kkt
