#pragma once
/// @file block_ldl.hpp
/// Sparse LDL^T of a symmetric indefinite matrix with static 1x1 and 2x2 pivots:
///   P A P^T = L D L^T,  L unit lower block-triangular,  D block diagonal,
/// where the 2x2 blocks and their order are the nodes of an elimination order (pair_order.hpp:
/// a constraint row and a variable it constrains, or a variable without a diagonal and one it
/// couples to, ordered by AMD on the graph of the pairs). A KKT matrix's constraint rows have no
/// diagonal, so a 1x1 pivot on one is zero whatever the order; the 2x2 block [w a; a 0] with a != 0
/// is not, and by Sylvester's law of inertia the eigenvalues of the D blocks count A's negative
/// eigenvalues, which is what Ipopt's inertia correction asks of its linear solver. This is the
/// static pivoting with a matching that Pardiso uses (Schenk and Gaertner 2006), without its
/// pivoting inside supernodes: the factorization is up-looking (Davis, "Algorithm 849: LDL", 2005)
/// on 2x2 blocks. A pivot eigenvalue below `tiny` in magnitude is moved to +-tiny and counted; the
/// caller refines the solution. Fast where its pivots hold (no search, no delayed rows, no
/// dense fronts); where they do not, kkt_solver.hpp turns to MultifrontalLdl.
#include <Eigen/Core>
#include <vector>

#include "ocp/solve/kkt/pair_order.hpp"
#include "ocp/solve/kkt/symmetric_pattern.hpp"

namespace gaitopt::ocp::kkt {

class BlockLdl {
 public:
  /// The block elimination tree of the order's nodes (one or two rows each).
  /// @throws std::invalid_argument if the order does not list every row once in such nodes.
  BlockLdl(const SymmetricPattern& pattern, const EliminationOrder& order);

  /// Numerical factorization of the matrix with this pattern and `values` (same order as the
  /// pattern's entries).
  void factorize(const double* values, double tiny);
  /// x := A^{-1} x for the last factorized A (up to the perturbed pivots).
  void solve(double* x) const;

  int negativeEigenvalues() const { return negative_; }
  int perturbedPivots() const { return perturbed_; }
  int blocks() const { return static_cast<int>(first_.size()); }

 private:
  using Mat2 = Eigen::Matrix2d;
  using Vec2 = Eigen::Vector2d;
  /// Where one entry of A lands in the permuted upper block pattern: block slot, element.
  struct Scatter {
    int entry, slot, element, mirror;  // mirror: the transposed element inside a diagonal block
  };

  void formBlocks(int n, const EliminationOrder& order);
  void scatterPattern(const SymmetricPattern& pattern);
  void eliminationTree();
  void eliminateBlockRow(int k, double tiny);
  void pivot(int k, Mat2 d, double tiny);
  bool single(int k) const { return second_[k] < 0; }

  std::vector<int> blockOf_, offsetOf_;  // row -> its block, its place (0, 1) in the block
  std::vector<int> first_, second_;      // block -> its rows (second -1: a 1x1 pivot)
  std::vector<int> cp_, ci_;             // upper block pattern of P A P^T by columns
  std::vector<Scatter> scatter_;
  std::vector<int> lp_, parent_, lnz_, li_;
  std::vector<int> rowStart_, rowBlocks_;  // nonzero blocks of each block row of L, in order
  std::vector<Mat2> cx_, lx_, dinv_, y_;
  mutable std::vector<Vec2> solution_;  // solve()'s workspace, kept between Ipopt's many solves
  int negative_ = 0;
  int perturbed_ = 0;
};

}  // namespace gaitopt::ocp::kkt
