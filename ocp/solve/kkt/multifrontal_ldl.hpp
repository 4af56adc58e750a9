#pragma once
/// @file multifrontal_ldl.hpp
/// Sparse LDL^T of a symmetric indefinite matrix, P A P^T = L D L^T with D of 1x1 and 2x2
/// blocks, by the multifrontal method with the pivots chosen during the factorization (Duff and
/// Reid, "The multifrontal solution of indefinite sparse symmetric linear equations", ACM TOMS
/// 9, 1983): each supernode of the assembly tree (assembly_tree.hpp) is a dense front that sums
/// its rows of A and its children's contribution blocks and eliminates its fully summed rows
/// with threshold pivoting (front_ldl.hpp); a row no stable pivot takes is delayed to the parent
/// front. The order is a starting point, not a promise: a zero or small diagonal is skipped over
/// inside its front instead of being clamped. By Sylvester's law of inertia the eigenvalues of D
/// count A's negative eigenvalues, which Ipopt's inertia correction asks of its linear solver.
#include <Eigen/Core>
#include <vector>

#include "ocp/solve/kkt/assembly_tree.hpp"
#include "ocp/solve/kkt/front_ldl.hpp"
#include "ocp/solve/kkt/symmetric_pattern.hpp"

namespace gaitopt::ocp::kkt {

/// Passes of the symmetric equilibration: a few bring every row's largest entry within a factor
/// of two or so of 1 (Ruiz 2001 converges linearly with rate 1/2).
inline constexpr int kEquilibrationPasses = 3;

class MultifrontalLdl {
 public:
  /// The symbolic analysis: the assembly tree of this pattern under this order, supernodes
  /// below `mergeBelow` columns merged (analyseAssemblyTree).
  MultifrontalLdl(const SymmetricPattern& pattern, const EliminationOrder& order,
                  int mergeBelow = kAmalgamationColumns);

  /// Numerical factorization of the matrix with this pattern and `values` (same order as the
  /// pattern's entries), equilibrated (S A S, multifrontal_ldl.cpp), its pivots chosen by `test`
  /// (front_ldl.hpp) with test.tiny relative to the largest entry of S A S: a pivot eigenvalue
  /// below it in magnitude, which only a (nearly) singular matrix leaves, is moved to +-tiny
  /// and counted.
  void factorize(const double* values, const PivotTest& test);
  /// x := A^{-1} x for the last factorized A (up to the perturbed pivots).
  void solve(double* x) const;

  int negativeEigenvalues() const { return negative_; }
  int perturbedPivots() const { return perturbed_; }
  /// Rows eliminated in a later front than the order put them in, counted once per front passed.
  int delayedPivots() const { return delayed_; }
  int supernodes() const { return tree_.supernodes(); }

 private:
  /// One front: its rows (eliminated ones first, then the ones it delayed, then the rows below
  /// it), and its first `fullySummed` columns (the panel), which after the factorization hold
  /// L's columns for the eliminated rows and, below and right of them, the delayed rows' part of
  /// the contribution block its parent adds up (lower triangle), read in place; and D^{-1}. The
  /// rest of the contribution block, the rows below the fully summed ones, waits on a stack
  /// (multifrontal_ldl.cpp) until the parent is assembled.
  struct FrontFactor {
    std::vector<int> rows;
    int fullySummed = 0;
    int pivots = 0;
    Eigen::MatrixXd matrix;
    std::vector<double> inverseDiagonal, inverseOffDiagonal;
  };

  void equilibrate(const double* values);
  int assemble(int s, const double* values);
  void factorizeFront(int s, const double* values, const PivotTest& test);
  void pushContribution(int s, int rows);

  SymmetricPattern pattern_;
  AssemblyTree tree_;
  std::vector<int> columnOf_;  // column of each stored entry
  std::vector<std::vector<int>> children_;
  std::vector<FrontFactor> factors_;
  std::vector<int> place_;              // row -> its place in the front being assembled
  std::vector<int> childPlace_;         // a child's row -> its place in that front
  std::vector<double*> diagonal_;       // that front's column j from its diagonal down
  std::vector<double> scale_, scaled_;  // S, and the values of S A S
  /// The front being factorized's rows below its fully summed ones, by columns (square).
  std::vector<double> below_;
  /// The contribution blocks' rows below their fronts' fully summed ones, waiting for their
  /// parents: each one's lower triangle packed by columns, from stackStart_[s].
  std::vector<double> stack_;
  std::vector<size_t> stackStart_;
  size_t stackTop_ = 0;
  Eigen::MatrixXd workspace_;  // factorFront's
  FrontPivots pivots_;
  std::vector<int> permuted_;
  mutable std::vector<double> work_;
  int negative_ = 0, perturbed_ = 0, delayed_ = 0;
};

}  // namespace gaitopt::ocp::kkt
