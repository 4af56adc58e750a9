// Lemke's method on LCPs with hand-checked solutions, degenerate and unsolvable problems, and
// random positive definite problems checked for feasibility and complementarity.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

#include "sim/contact/lemke.hpp"

namespace gaitopt::test {
namespace {

using sim::LemkeStatus;
using sim::solveLcp;

/// Largest violation of z >= 0, w = M z + q >= 0, z^T w = 0, with w recomputed here.
double lcpResidual(const Eigen::MatrixXd& m, const Eigen::VectorXd& q, const Eigen::VectorXd& z) {
  const Eigen::VectorXd w = m * z + q;
  return std::max({std::abs(z.dot(w)), -z.minCoeff(), -w.minCoeff(), 0.0});
}

void expectSolves(const Eigen::MatrixXd& m, const Eigen::VectorXd& q,
                  const Eigen::VectorXd& z_expected) {
  const sim::LemkeResult r = solveLcp(m, q);
  ASSERT_EQ(r.status, LemkeStatus::kSolved);
  EXPECT_LT((r.z - z_expected).lpNorm<Eigen::Infinity>(), 1e-12) << r.z.transpose();
  EXPECT_LT((r.w - (m * r.z + q)).lpNorm<Eigen::Infinity>(), 1e-12);
  EXPECT_LT(lcpResidual(m, q, r.z), 1e-10);
}

TEST(Lemke, NonNegativeQGivesTheTrivialSolutionWithoutPivots) {
  const Eigen::Matrix2d m{{-1, 5}, {3, -2}};
  const sim::LemkeResult r = solveLcp(m, Eigen::Vector2d(0, 1));
  EXPECT_EQ(r.status, LemkeStatus::kSolved);
  EXPECT_EQ(r.pivots, 0);
  EXPECT_EQ(r.z, Eigen::Vector2d::Zero());
  EXPECT_EQ(r.w, Eigen::Vector2d(0, 1));
}

TEST(Lemke, TwoByTwoPMatrixBothActive) {
  // 2 z1 + z2 = 5, z1 + 2 z2 = 6  ->  z = (4/3, 7/3), w = 0.
  expectSolves(Eigen::Matrix2d{{2, 1}, {1, 2}}, Eigen::Vector2d(-5, -6),
               Eigen::Vector2d(4.0 / 3, 7.0 / 3));
}

TEST(Lemke, TwoByTwoPMatrixOneActive) {
  // z1 = 0: w2 = 2 z2 - 4 = 0 -> z2 = 2, w1 = z2 + 1 = 3 >= 0.
  expectSolves(Eigen::Matrix2d{{2, 1}, {1, 2}}, Eigen::Vector2d(1, -4), Eigen::Vector2d(0, 2));
}

TEST(Lemke, ThreeByThreeMixedSupport) {
  // z2 = 0: 4 z1 = 3, 4 z3 = 3; w2 = -z1 - z3 + 2 = 1/2 >= 0.
  const Eigen::Matrix3d m{{4, -1, 0}, {-1, 4, -1}, {0, -1, 4}};
  expectSolves(m, Eigen::Vector3d(-3, 2, -3), Eigen::Vector3d(0.75, 0, 0.75));
}

TEST(Lemke, DegenerateQWithZerosNeedsSeveralPivots) {
  // Positive definite (leading minors 1, 1, 1); the only solution is z = (1, 1, 1), w = 0, so
  // every z_i must enter the basis although two rows of q are already complementary at z = 0.
  const Eigen::Matrix3d m{{1, -1, 0}, {-1, 2, -1}, {0, -1, 2}};
  const Eigen::Vector3d q(0, 0, -1);
  expectSolves(m, q, Eigen::Vector3d(1, 1, 1));
  EXPECT_GE(solveLcp(m, q).pivots, 4);  // z0 in, z3, z2, z1 in, z0 out
}

TEST(Lemke, TiedInitialRatiosAreBrokenLexicographically) {
  // All q_i equal: the first ratio test ties three ways. P-matrix (det 9), z = (1/3, 1/3, 1/3).
  const Eigen::Matrix3d m{{1, 2, 0}, {0, 1, 2}, {2, 0, 1}};
  expectSolves(m, Eigen::Vector3d(-1, -1, -1), Eigen::Vector3d::Constant(1.0 / 3));
}

TEST(Lemke, DegenerateSolutionEndsAsSoonAsZ0CanLeave) {
  // 4 z1 - z2 = 1, -z1 + 4 z2 = 1 -> z = (1/3, 1/3, 0), and w3 = z1 - z2 = 0 too. At the third
  // pivot z0 ties with w3 for leaving; letting z0 leave ends the run there (the lexicographic
  // rule alone would take a fourth pivot).
  const Eigen::Matrix3d m{{4, -1, 1}, {-1, 4, -1}, {1, -1, 3}};
  const Eigen::Vector3d q(-1, -1, 0);
  expectSolves(m, q, Eigen::Vector3d(1.0 / 3, 1.0 / 3, 0));
  EXPECT_EQ(solveLcp(m, q).pivots, 3);
}

TEST(Lemke, InfeasibleScalarLcpEndsOnARay) {
  // w = -z - 1 < 0 for every z >= 0.
  const sim::LemkeResult r =
      solveLcp(Eigen::Matrix<double, 1, 1>(-1), Eigen::VectorXd::Constant(1, -1));
  EXPECT_EQ(r.status, LemkeStatus::kRayTermination);
  EXPECT_STREQ(sim::toString(r.status), "ray_termination");
}

TEST(Lemke, InfeasibleSkewLcpEndsOnARay) {
  // M = [[0, -1], [1, 0]] is positive semidefinite, but w1 = -z2 - 1 < 0: no feasible point.
  const sim::LemkeResult r = solveLcp(Eigen::Matrix2d{{0, -1}, {1, 0}}, Eigen::Vector2d(-1, -1));
  EXPECT_EQ(r.status, LemkeStatus::kRayTermination);
}

TEST(Lemke, StopsAtThePivotLimit) {
  const Eigen::Matrix3d m{{1, -1, 0}, {-1, 2, -1}, {0, -1, 2}};
  const sim::LemkeResult r = solveLcp(m, Eigen::Vector3d(0, 0, -1), {.max_pivots = 2});
  EXPECT_EQ(r.status, LemkeStatus::kPivotLimit);
  EXPECT_EQ(r.pivots, 2);
}

TEST(Lemke, RandomPositiveDefiniteProblemsAreSolved) {
  std::mt19937 rng(20240611);
  std::normal_distribution<double> normal;
  for (int n = 2; n <= 10; ++n) {
    for (int trial = 0; trial < 50; ++trial) {
      Eigen::MatrixXd a(n, n);
      Eigen::VectorXd q(n);
      for (int i = 0; i < n; ++i) {
        q(i) = normal(rng);
        for (int j = 0; j < n; ++j) a(i, j) = normal(rng);
      }
      const Eigen::MatrixXd m = a * a.transpose() / n + 0.01 * Eigen::MatrixXd::Identity(n, n);
      const sim::LemkeResult r = solveLcp(m, q);
      ASSERT_EQ(r.status, LemkeStatus::kSolved) << "n = " << n << ", trial " << trial;
      EXPECT_LT(lcpResidual(m, q, r.z), 1e-9) << "n = " << n << ", trial " << trial;
      EXPECT_LE(r.pivots, 2 * n + 1) << "n = " << n << ", trial " << trial;
    }
  }
}

TEST(Lemke, RejectsBadInput) {
  EXPECT_THROW(solveLcp(Eigen::MatrixXd::Identity(2, 3), Eigen::Vector2d(-1, -1)),
               std::invalid_argument);
  EXPECT_THROW(solveLcp(Eigen::Matrix2d::Identity(), Eigen::Vector3d(-1, -1, -1)),
               std::invalid_argument);
  EXPECT_THROW(solveLcp(Eigen::Matrix2d::Identity(), Eigen::Vector2d(-1, NAN)),
               std::invalid_argument);
  EXPECT_THROW(solveLcp(Eigen::Matrix2d{{1, INFINITY}, {0, 1}}, Eigen::Vector2d(-1, -1)),
               std::invalid_argument);
  EXPECT_THROW(solveLcp(Eigen::Matrix2d::Identity(), Eigen::Vector2d(-1, -1), {.max_pivots = 0}),
               std::invalid_argument);
}

}  // namespace
}  // namespace gaitopt::test
