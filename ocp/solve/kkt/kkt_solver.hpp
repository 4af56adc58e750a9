#pragma once
/// @file kkt_solver.hpp
/// Ipopt's augmented system solved by BlockLdl with pairs from kkt_pairs.hpp: what Pardiso's
/// phases 11 (analyse), 22 (factorize) and 33 (solve) do for Ipopt (pardiso_interface.cpp).
/// Why not MUMPS: on these problems (4 000 rows, 26 000 entries) MUMPS spends 3.7 ms on a
/// factorization of 2.7 Mflop, its bookkeeping per front rather than arithmetic, and two thirds
/// of a whole solve (results/solve_profile.md); Debian ships no other solver Ipopt can load.
/// What static pivots cost: no pivoting inside the elimination, so the pairs can leave a zero
/// pivot, or a small one that loses the solution's digits or flips the inertia's count. Such a
/// matrix is factorized by MUMPS instead (mumps_factor.hpp), as `linear_solver: mumps` would
/// have: a zero pivot, or an inertia other than a KKT matrix's, at once; lost digits when
/// refinement cannot recover them. Before, the zero pivot was clamped, which gave another
/// inertia, the lost digits were Ipopt's to refine, which stalled, and a flipped count made
/// Ipopt regularise a matrix that needed none.
#include <memory>
#include <vector>

#include "ocp/solve/kkt/block_ldl.hpp"
#include "ocp/solve/kkt/mumps_factor.hpp"
#include "ocp/solve/kkt/symmetric_pattern.hpp"

namespace gaitopt::ocp::kkt {

class KktSolver {
 public:
  explicit KktSolver(SymmetricPattern pattern);

  /// Pairs the rows by these values and orders the blocks.
  void analyse(const double* values);
  /// Factorizes A(values); analyses again first if a variable row's diagonal has become zero
  /// since (Ipopt's first matrix, for the least-squares multipliers, has an identity there).
  /// On a zero static pivot, or an inertia other than one negative eigenvalue per constraint
  /// row, MUMPS factorizes A instead. @throws SingularMatrix from MUMPS.
  void factorize(const double* values);
  /// rhs := A^{-1} rhs, refined against A(values) while Ipopt's residual ratio is missed, at most
  /// max(2, refinementSteps) steps; if it is still missed, MUMPS factorizes A and solves again.
  /// Returns the refinement steps of the last solution.
  int solve(const double* values, double* rhs, int refinementSteps);

  /// A's negative eigenvalues, by the last factorization.
  int negativeEigenvalues() const;
  int analyses() const { return analyses_; }
  /// The factorizations MUMPS made in place of the static pivots'.
  int fallbacks() const { return fallbacks_; }

 private:
  bool lostADiagonal(const double* values) const;
  void factorizeWithMumps(const double* values);
  void applyInverse(double* x) const;
  /// Solves and refines in place; returns the residual ratio reached and sets the steps taken.
  double solveAndRefine(const double* values, double* rhs, int refinementSteps, int& steps) const;

  SymmetricPattern pattern_;
  int constraintStart_;
  std::vector<char> mustPair_;  // row -> a variable row seen with a zero diagonal
  std::vector<char> paired_;    // row -> in a 2x2 pivot
  std::unique_ptr<BlockLdl> ldl_;
  std::unique_ptr<MumpsFactor> mumps_;  // made at the first fallback
  /// Whose factors of the last factorized A the solves use: the static pivots', MUMPS's, or the
  /// static pivots' after MUMPS found A singular in a solve (not to be asked again).
  enum class Factor { kStatic, kMumps, kStaticMumpsRefused };
  Factor factor_ = Factor::kStatic;
  int analyses_ = 0;
  int fallbacks_ = 0;
};

}  // namespace gaitopt::ocp::kkt
