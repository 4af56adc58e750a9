#pragma once
/// @file front_ldl.hpp
/// The partial LDL^T of one dense front of a multifrontal factorization, with the pivots chosen
/// inside it. The front's first p rows (its fully summed variables) may be eliminated, in any
/// order; the rest only receive the Schur complement. A 1x1 pivot a_jj is taken if
/// |a_jj| >= u max_i |a_ij|; else a 2x2 pivot D on j and its largest fully summed neighbour r if
/// |D^{-1}| [max_i |a_ij|; max_i |a_ir|] <= [1/u; 1/u] (i outside the pivot, over the whole
/// front): the threshold test of Duff and Reid (1983) as MA57 and MUMPS apply it, which bounds
/// L's entries by 1/u. A small u delays few rows and keeps the order's fill; a large one keeps
/// more digits: kkt_solver.hpp starts small and raises it when a solve is inexact, as Ipopt
/// raises MUMPS's pivot tolerance. A fully summed variable that no acceptable pivot takes is
/// delayed: left to the parent front, where more of its row is summed. A root front has nothing
/// to delay to, and every row of it is fully summed; there it is Bunch and Kaufman's (1977)
/// partial pivoting, which always finds a pivot.
#include <Eigen/Core>
#include <vector>

namespace gaitopt::ocp::kkt {

/// How one front was eliminated.
struct FrontPivots {
  int pivots = 0;  ///< rows eliminated (the first ones after the permutation)
  /// The front's rows as permuted: place i now holds the row that was at permutation[i].
  std::vector<int> permutation;
  /// D^{-1} by eliminated row: its diagonal, and for the first row of a 2x2 pivot the
  /// off-diagonal element coupling it to the next row (0 otherwise).
  std::vector<double> inverseDiagonal, inverseOffDiagonal;
  int negative = 0;   ///< negative eigenvalues of D
  int perturbed = 0;  ///< pivot eigenvalues below `tiny` in magnitude, moved to +-tiny
};

/// The pivot test's threshold u in (0, 1/2], and the pivot magnitude `tiny` below which a pivot
/// eigenvalue is moved to +-tiny (and counted) instead of divided by.
struct PivotTest {
  double threshold = 0.01;
  double tiny = 0.0;
};

/// Eliminates what it can of the first p rows (its fully summed ones) of the symmetric m x m
/// front f given as its first p columns `panel` = f(:, 0:p) and `below` = f(p:, p:), the rows
/// below the fully summed ones: the fully summed block f(0:p, 0:p) is stored whole, the rest by
/// its lower triangle. On return, the panel's first `pivots` columns hold L (unit diagonal
/// implied; a 2x2 pivot's L entry is 0), and f(pivots:, pivots:) the lower triangle of the
/// contribution block, delayed rows first (the delayed ones in the panel, the rest in `below`).
/// `result` and `workspace` are overwritten; passing the same ones again saves allocations.
void factorFront(Eigen::Ref<Eigen::MatrixXd> panel, Eigen::Ref<Eigen::MatrixXd> below, bool root,
                 const PivotTest& test, FrontPivots& result, Eigen::MatrixXd& workspace);

}  // namespace gaitopt::ocp::kkt
