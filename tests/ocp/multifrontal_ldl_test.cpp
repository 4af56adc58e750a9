// gaitopt's multifrontal LDL^T (ocp/solve/kkt/): the assembly tree against symbolic elimination
// on a dense matrix, one front's partial factorization against the dense Schur complement and
// the threshold's bound on L, and whole factorizations against dense eigenvalues and solves,
// under orders chosen to put zero pivots first.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <numeric>
#include <random>
#include <vector>

#include "ocp/solve/kkt/assembly_tree.hpp"
#include "ocp/solve/kkt/front_ldl.hpp"
#include "ocp/solve/kkt/multifrontal_ldl.hpp"
#include "support/dense_symmetric.hpp"

namespace gaitopt::ocp::kkt {
namespace {

using test::backwardError;
using test::Lower;
using test::lowerOf;
using test::negativeEigenvalues;

/// A random sparse symmetric matrix: about `density` of the off-diagonal pairs coupled, a
/// third of the diagonal zero, the rest of both signs over six decades.
Eigen::MatrixXd randomSymmetric(std::mt19937& g, int n, double density) {
  std::uniform_real_distribution<double> u(-1, 1);
  Eigen::MatrixXd a = Eigen::MatrixXd::Zero(n, n);
  for (int i = 0; i < n; ++i) {
    if (u(g) > -0.33) a(i, i) = u(g) * std::pow(10.0, 3 * u(g));
    for (int j = 0; j < i; ++j)
      if ((u(g) + 1) / 2 < density) a(i, j) = a(j, i) = u(g);
  }
  return a;
}

/// The nonzero rows below the diagonal of every column of L for the matrix permuted by `order`,
/// by eliminating a dense boolean pattern (no cancellation).
std::vector<std::vector<int>> denseSymbolic(const Eigen::MatrixXd& a,
                                            const std::vector<int>& order) {
  const int n = static_cast<int>(order.size());
  std::vector<std::vector<char>> nz(n, std::vector<char>(n, 0));
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) nz[i][j] = a(order[i], order[j]) != 0.0;
  std::vector<std::vector<int>> structure(n);
  for (int k = 0; k < n; ++k) {
    for (int i = k + 1; i < n; ++i)
      if (nz[i][k]) structure[k].push_back(i);
    for (int i : structure[k])
      for (int j : structure[k]) nz[i][j] = 1;
  }
  return structure;
}

TEST(AssemblyTree, SupernodesHoldTheColumnsOfLAsSymbolicEliminationFindsThem) {
  std::mt19937 g(5);
  for (int trial = 0; trial < 50; ++trial) {
    const int n = 5 + trial % 30;
    const Eigen::MatrixXd a = randomSymmetric(g, n, 0.15);
    std::vector<int> given(n);
    std::iota(given.begin(), given.end(), 0);
    std::shuffle(given.begin(), given.end(), g);
    const AssemblyTree tree =
        analyseAssemblyTree(lowerOf(a).pattern, EliminationOrder::ofRows(given));
    const std::vector<std::vector<int>> structure = denseSymbolic(a, tree.order);
    std::vector<int> owner(n, -1);  // position -> its supernode
    for (int s = 0; s < tree.supernodes(); ++s)
      for (int q = tree.columnStart[s]; q < tree.columnStart[s + 1]; ++q) {
        EXPECT_EQ(owner[tree.columns[q]], -1) << "a column in two supernodes";
        owner[tree.columns[q]] = s;
      }
    EXPECT_EQ(std::count(owner.begin(), owner.end(), -1), 0) << "every column in one";
    for (int s = 0; s < tree.supernodes(); ++s) {
      EXPECT_GT(tree.parent[s] < 0 ? tree.supernodes() : tree.parent[s], s) << "children first";
      std::vector<char> inFront(n, 0);  // the supernode's columns and the rows below it
      for (int q = tree.columnStart[s]; q < tree.columnStart[s + 1]; ++q)
        inFront[tree.columns[q]] = 1;
      for (int q = tree.rowStart[s]; q < tree.rowStart[s + 1]; ++q) {
        const int i = tree.position[tree.rows[q]];
        EXPECT_NE(owner[i], s);
        inFront[i] = 1;
        // a row below s is eliminated by an ancestor
        int up = s;
        while (up >= 0 && up != owner[i]) up = tree.parent[up];
        EXPECT_EQ(up, owner[i]) << "trial " << trial;
      }
      for (int q = tree.columnStart[s]; q < tree.columnStart[s + 1]; ++q) {
        const int j = tree.columns[q];
        for (int i : structure[j]) EXPECT_TRUE(inFront[i]) << "trial " << trial << " column " << j;
      }
    }
  }
}

TEST(AssemblyTree, FundamentalSupernodesAreExactAndSmallOnesMerge) {
  // A dense matrix is one fundamental supernode. A tridiagonal one eliminated in order is a
  // chain of one-column supernodes (column j of L holds only row j + 1; the last two columns
  // are a dense 2x2 and one supernode), merged into groups of
  // fewer than 2 kAmalgamationColumns. So are the n - 1 leaves of an arrow whose tip is last.
  const int n = 40;
  std::vector<int> inOrder(n);
  std::iota(inOrder.begin(), inOrder.end(), 0);
  const EliminationOrder rows = EliminationOrder::ofRows(inOrder);
  const AssemblyTree dense =
      analyseAssemblyTree(lowerOf(Eigen::MatrixXd::Ones(n, n)).pattern, rows, 1);
  EXPECT_EQ(dense.supernodes(), 1);
  EXPECT_EQ(dense.rows.size(), 0U);
  Eigen::MatrixXd chain = Eigen::MatrixXd::Identity(n, n);
  for (int i = 1; i < n; ++i) chain(i, i - 1) = chain(i - 1, i) = 0.5;
  EXPECT_EQ(analyseAssemblyTree(lowerOf(chain).pattern, rows, 1).supernodes(), n - 1);
  const AssemblyTree line = analyseAssemblyTree(lowerOf(chain).pattern, rows);
  EXPECT_EQ(line.supernodes(), 3);  // 16 + 16 columns would not merge: 15 + 16 + 9
  Eigen::MatrixXd arrow = Eigen::MatrixXd::Identity(n, n);
  arrow.row(n - 1).setConstant(0.1);
  arrow.col(n - 1).setConstant(0.1);
  arrow(n - 1, n - 1) = 1.0;
  const AssemblyTree star = analyseAssemblyTree(lowerOf(arrow).pattern, rows);
  EXPECT_LT(star.supernodes(), n - 1);
  for (int s = 0; s < star.supernodes(); ++s)
    EXPECT_LE(star.columnStart[s + 1] - star.columnStart[s], 2 * kAmalgamationColumns);
}

TEST(AssemblyTree, RefusesAnOrderThatIsNotAPermutation) {
  const Lower l = lowerOf(Eigen::Matrix3d::Identity());
  EXPECT_THROW(analyseAssemblyTree(l.pattern, EliminationOrder::ofRows({0, 1})),
               std::invalid_argument);
  EXPECT_THROW(analyseAssemblyTree(l.pattern, EliminationOrder::ofRows({0, 1, 1})),
               std::invalid_argument);
  EXPECT_THROW(analyseAssemblyTree(l.pattern, EliminationOrder::ofRows({0, 1, 3})),
               std::invalid_argument);
}

TEST(FrontLdl, EliminatesWithLBoundedByTheThresholdAndLeavesTheSchurComplement) {
  std::mt19937 g(11);
  std::uniform_real_distribution<double> u(-1, 1);
  int delayed = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const int m = 4 + trial % 12, p = 1 + trial % (m - 1);
    Eigen::MatrixXd a = Eigen::MatrixXd::NullaryExpr(m, m, [&] { return u(g); });
    a = (a + a.transpose()).eval();
    for (int i = 0; i < p; ++i)  // small or zero diagonals among the fully summed rows
      if (u(g) > 0) a(i, i) *= trial % 3 == 0 ? 0.0 : 1e-4;
    Eigen::MatrixXd f = a;
    FrontPivots piv;
    Eigen::MatrixXd workspace;
    factorFront(f.leftCols(p), f.bottomRightCorner(m - p, m - p), false, {0.01, 1e-30}, piv,
                workspace);
    const int k = piv.pivots;
    delayed += p - k;
    Eigen::PermutationMatrix<Eigen::Dynamic> perm(m);
    for (int i = 0; i < m; ++i) perm.indices()[i] = piv.permutation[i];
    const Eigen::MatrixXd b = perm.transpose() * a * perm;  // b(i, j) = a(perm i, perm j)
    if (k == 0) continue;                                   // all delayed: f is a, untouched
    Eigen::MatrixXd l = f.leftCols(k).triangularView<Eigen::UnitLower>();
    Eigen::MatrixXd dinv = Eigen::MatrixXd::Zero(k, k);
    for (int i = 0; i < k; ++i) {
      dinv(i, i) = piv.inverseDiagonal[i];
      if (i + 1 < k) dinv(i, i + 1) = dinv(i + 1, i) = piv.inverseOffDiagonal[i];
    }
    const Eigen::MatrixXd d = dinv.inverse();
    // L D L^T reproduces the eliminated columns, and the rest is b's Schur complement.
    const Eigen::MatrixXd ldl = l * d * l.topRows(k).transpose();
    EXPECT_LT((ldl - b.leftCols(k)).cwiseAbs().maxCoeff(), 1e-9) << "trial " << trial;
    const Eigen::MatrixXd schur =
        b.bottomRightCorner(m - k, m - k) -
        b.bottomLeftCorner(m - k, k) * b.topLeftCorner(k, k).inverse() * b.topRightCorner(k, m - k);
    const Eigen::MatrixXd contribution = f.bottomRightCorner(m - k, m - k);
    EXPECT_LT((contribution.triangularView<Eigen::Lower>().toDenseMatrix() -
               schur.triangularView<Eigen::Lower>().toDenseMatrix())
                  .cwiseAbs()
                  .maxCoeff(),
              1e-8)
        << "trial " << trial;
    // The threshold test (u = 0.01) bounds every entry of L by 1 / u.
    EXPECT_LE(
        f.leftCols(k).triangularView<Eigen::StrictlyLower>().toDenseMatrix().cwiseAbs().maxCoeff(),
        1.0 / 0.01 + 1e-9);
  }
  EXPECT_GT(delayed, 0) << "the family has fronts whose pivots must wait";
}

TEST(FrontLdl, ARootFrontEliminatesEveryRowEvenWithAZeroDiagonal) {
  Eigen::Matrix3d a;
  a << 0, 1, 0, 1, 0, 2, 0, 2, 0;  // no usable 1x1 pivot on the diagonal
  Eigen::MatrixXd f = a;
  FrontPivots piv;
  Eigen::MatrixXd workspace;
  factorFront(f, f.bottomRightCorner(0, 0), true, {0.01, 1e-30}, piv, workspace);
  EXPECT_EQ(piv.pivots, 3);
  EXPECT_EQ(piv.perturbed, 1) << "the matrix is singular: one pivot is clamped";
  Eigen::Matrix2d nonsingular;
  nonsingular << 0, 1, 1, 0;
  Eigen::MatrixXd f2 = nonsingular;
  FrontPivots p2;
  factorFront(f2, f2.bottomRightCorner(0, 0), true, {0.01, 1e-30}, p2, workspace);
  EXPECT_EQ(p2.pivots, 2);
  EXPECT_EQ(p2.perturbed, 0);
  EXPECT_EQ(p2.negative, 1);
}

/// An order that eliminates the zero-diagonal rows first, where no pivot order could use them.
std::vector<int> zeroDiagonalsFirst(const Eigen::MatrixXd& a) {
  std::vector<int> order(a.rows());
  std::iota(order.begin(), order.end(), 0);
  std::stable_partition(order.begin(), order.end(), [&](int i) { return a(i, i) == 0.0; });
  return order;
}

TEST(MultifrontalLdl, SolvesAndCountsTheInertiaLikeDenseAlgebraUnderOrdersThatPutZerosFirst) {
  std::mt19937 g(3);
  int tested = 0, delayed = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const int n = 6 + trial % 60;
    const Eigen::MatrixXd a = randomSymmetric(g, n, 3.0 / n);
    const Eigen::VectorXd ev = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(a).eigenvalues();
    if (ev.cwiseAbs().minCoeff() < 1e-6 * ev.cwiseAbs().maxCoeff()) continue;  // near singular
    ++tested;
    const Lower l = lowerOf(a);
    MultifrontalLdl ldl(l.pattern, EliminationOrder::ofRows(zeroDiagonalsFirst(a)));
    ldl.factorize(l.values.data(), {0.01, 1e-30 * a.cwiseAbs().maxCoeff()});
    delayed += ldl.delayedPivots();
    EXPECT_EQ(ldl.perturbedPivots(), 0) << "trial " << trial;
    EXPECT_EQ(ldl.negativeEigenvalues(), negativeEigenvalues(a)) << "trial " << trial;
    const Eigen::VectorXd b = Eigen::VectorXd::Random(n);
    Eigen::VectorXd x = b;
    ldl.solve(x.data());
    EXPECT_LT(backwardError(a, x, b), 1e-13) << "trial " << trial;
  }
  EXPECT_GT(tested, 100);
  EXPECT_GT(delayed, 50) << "these orders make the factorization pivot";
}

TEST(MultifrontalLdl, AZeroPivotInAChildFrontIsDelayedToItsParentNotClamped) {
  // Rows 0 and 1 each couple only to row 2, so each is a front of its own; row 0's diagonal is
  // zero and its front has no other fully summed row to pair it with: a static order would
  // clamp that pivot; here it waits for row 2's front.
  Eigen::Matrix3d a;
  a << 0, 0, 1, 0, 2, 1, 1, 1, 3;
  const Lower l = lowerOf(a);
  MultifrontalLdl ldl(l.pattern, EliminationOrder::ofRows({0, 1, 2}),
                      1);  // no merging: three fronts
  EXPECT_EQ(ldl.supernodes(), 3);
  ldl.factorize(l.values.data(), {0.01, 1e-30});
  EXPECT_EQ(ldl.delayedPivots(), 1);
  EXPECT_EQ(ldl.perturbedPivots(), 0);
  EXPECT_EQ(ldl.negativeEigenvalues(), negativeEigenvalues(a));
  Eigen::Vector3d x(1, 2, 3);
  ldl.solve(x.data());
  EXPECT_LT((a * x - Eigen::Vector3d(1, 2, 3)).norm(), 1e-14);
}

}  // namespace
}  // namespace gaitopt::ocp::kkt
