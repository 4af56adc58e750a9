#pragma once
/// @file kkt_solver.hpp
/// Ipopt's augmented system solved in the order pair_order.hpp gives the pairs of
/// kkt_pairs.hpp: what Pardiso's phases 11 (analyse), 22 (factorize) and 33 (solve) do for Ipopt
/// (pardiso_interface.cpp). Two factorizations share that order: BlockLdl's static 2x2 pivots,
/// fast (no pivot search, no dense fronts) and enough for the five-link default and RABBIT at
/// every iteration, and MultifrontalLdl, which chooses its pivots inside the factorization and
/// takes over, for the rest of the solve, at the first matrix the static pivots fail on.
/// Why not MUMPS: on these problems (4 000 rows, 26 000 entries) MUMPS spends 3.7 ms on a
/// factorization of 2.7 Mflop, its bookkeeping per front rather than arithmetic, and two thirds
/// of a whole solve (results/solve_profile.md); Debian ships no other solver Ipopt can load.
/// The pivoting factorization's inertia is the matrix's (Sylvester's law) and Ipopt's to act on,
/// as MUMPS's is. MUMPS (mumps_factor.hpp) still takes the rare matrix it leaves with a pivot
/// below `tiny`, a (nearly) singular one, for MUMPS to call singular or not, and a solve that
/// refinement leaves less accurate than Ipopt asks under the largest pivot threshold. Before the
/// pivoting factorization, every matrix the static pivots failed on went to MUMPS: 803 of 1005
/// factorizations of the cost-of-transport solve (results/linear_solver_compare.csv of then).
#include <memory>
#include <vector>

#include "ocp/solve/kkt/block_ldl.hpp"
#include "ocp/solve/kkt/multifrontal_ldl.hpp"
#include "ocp/solve/kkt/mumps_factor.hpp"
#include "ocp/solve/kkt/pair_order.hpp"
#include "ocp/solve/kkt/symmetric_pattern.hpp"

namespace gaitopt::ocp::kkt {

class KktSolver {
 public:
  explicit KktSolver(SymmetricPattern pattern);

  /// Pairs the rows by these values, orders the pairs and analyses the assembly tree.
  void analyse(const double* values);
  /// Factorizes A(values); analyses again first if a variable row's diagonal has become zero
  /// since (Ipopt's first matrix, for the least-squares multipliers, has an identity there).
  /// The static pivots while they hold, then pivoting (kkt_solver.cpp says when); on a pivot
  /// below `tiny` there, MUMPS factorizes A instead. The thread's observer (kkt_observer.hpp),
  /// if set, then sees A and its count of negative eigenvalues. @throws SingularMatrix from MUMPS.
  void factorize(const double* values);
  /// rhs := A^{-1} rhs, refined against A(values) while Ipopt's residual ratio is missed: at
  /// most max(2, refinementSteps) steps, and with the static pivots more (up to 8) while each
  /// gains tenfold; if it is still missed, A is factorized again with a larger
  /// pivot threshold (kept for later matrices), and by MUMPS past the largest, and solved again.
  /// Returns the refinement steps of the last solution.
  int solve(const double* values, double* rhs, int refinementSteps);

  /// A's negative eigenvalues, by the last factorization.
  int negativeEigenvalues() const;
  int analyses() const { return analyses_; }
  /// The factorizations MUMPS made in place of gaitopt's.
  int fallbacks() const { return fallbacks_; }

 private:
  bool lostADiagonal(const double* values) const;
  /// factorize's choice of factorization (the observer, kkt_observer.hpp, sees its result).
  void chooseAndFactorize(const double* values);
  void factorizePivoting(const double* values);
  void factorizeWithMumps(const double* values);
  void applyInverse(double* x) const;
  /// Whether refinement takes another step after `steps`, the last of which gained `lastGain`.
  bool worthRefining(int steps, int refinementSteps, double lastGain) const;
  /// Solves and refines in place; returns the residual ratio reached and sets the steps taken.
  double solveAndRefine(const double* values, double* rhs, int refinementSteps, int& steps) const;

  SymmetricPattern pattern_;
  int constraintStart_;
  std::vector<char> mustPair_;  // row -> a variable row seen with a zero diagonal
  std::vector<char> paired_;    // row -> in a pair
  EliminationOrder order_;
  std::unique_ptr<BlockLdl> static_;
  std::unique_ptr<MultifrontalLdl> pivoting_;  // made at the first matrix the static pivots fail
  bool usePivoting_ = false;
  std::unique_ptr<MumpsFactor> mumps_;  // made at the first fallback
  /// Whose factors of the last factorized A the solves use: the static pivots', the pivoting
  /// ones', MUMPS's, or the pivoting ones' after MUMPS found A singular in a solve (not to be
  /// asked again).
  enum class Factor { kStatic, kPivoting, kMumps, kPivotingMumpsRefused };
  Factor factor_ = Factor::kStatic;
  int analyses_ = 0;
  int fallbacks_ = 0;
  double threshold_;  // the pivot test's u; kkt_solver.cpp says how it moves
};

}  // namespace gaitopt::ocp::kkt
