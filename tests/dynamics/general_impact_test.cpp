// The general impact of Mu (2004) sec. 2.4 (dynamics/impact/general_impact.hpp): with
// independent contacts it is the closed form (2.63-2.64); with dependent ones (rank r < 2k) the
// velocities after the impact are unique, whatever basis of the constraints is taken (2.72-2.74),
// and 2k - r impulse components are left free (2.75-2.78).
#include <random>

#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <Eigen/LU>

#include "dynamics/floating_base.hpp"
#include "dynamics/impact/general_impact.hpp"
#include "support/fixtures.hpp"

namespace gaitopt::test {
namespace {

Eigen::MatrixXd randomSpd(int n, std::mt19937& rng) {
  std::normal_distribution<double> g;
  Eigen::MatrixXd a(n, n);
  for (int i = 0; i < n * n; ++i) a(i) = g(rng);
  return a * a.transpose() + n * Eigen::MatrixXd::Identity(n, n);
}

Eigen::MatrixXd randomMatrix(int rows, int cols, std::mt19937& rng) {
  std::normal_distribution<double> g;
  Eigen::MatrixXd a(rows, cols);
  for (int i = 0; i < rows * cols; ++i) a(i) = g(rng);
  return a;
}

double kinetic(const Eigen::MatrixXd& d, const Eigen::VectorXd& v) {
  return 0.5 * v.dot(d * v);
}

/// The five-link robot's double impact as a constrained impact of its free-base chain: B and E
/// held, J = [J_B; J_E] (4 x 7), at a touchdown posture.
struct FiveLinkTouchdown {
  Eigen::MatrixXd d, j;
  Eigen::VectorXd qdot;
};

FiveLinkTouchdown fiveLinkTouchdown() {
  const dynamics::Model model = loadNamed("mu2004_five_link");
  VecD theta(5), dtheta(5);
  theta << 0.3, 0.1, 0.0, 2.7, 2.9;
  dtheta << 0.9, 0.3, 0.0, 1.2, -0.4;
  FiveLinkTouchdown t;
  t.d = dynamics::floatingBaseMassMatrix<double>(model, theta);
  t.j = Eigen::MatrixXd::Zero(4, 7);
  t.j.topLeftCorner(2, 2).setIdentity();
  t.j.bottomRows(2) = dynamics::floatingJacobian<double>(model.tipWeights(), theta);
  t.qdot = Eigen::VectorXd::Zero(7);
  t.qdot.tail(5) = dtheta;
  return t;
}

TEST(GeneralImpact, WithIndependentContactsItIsTheClosedForm) {
  const FiveLinkTouchdown t = fiveLinkTouchdown();
  const dynamics::GeneralImpact g = dynamics::generalImpact(t.d, t.j, t.qdot);
  EXPECT_EQ(g.rank, 4);
  EXPECT_EQ(g.undetermined, 0);
  // (2.63-2.64): F = -(J D^-1 J^T)^-1 J qdot-, qdot+ = qdot- + D^-1 J^T F.
  const Eigen::MatrixXd d_inv_jt = t.d.ldlt().solve(t.j.transpose());
  const Eigen::VectorXd f = -(t.j * d_inv_jt).lu().solve(t.j * t.qdot);
  EXPECT_LT((g.impulses - f).cwiseAbs().maxCoeff(), 1e-10 * f.cwiseAbs().maxCoeff());
  EXPECT_LT((g.qdot_plus - (t.qdot + d_inv_jt * f)).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_LT((t.j * g.qdot_plus).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(GeneralImpact, DependentContactsGiveTheSameVelocitiesAndLeaveImpulsesFree) {
  const FiveLinkTouchdown t = fiveLinkTouchdown();
  const dynamics::GeneralImpact full = dynamics::generalImpact(t.d, t.j, t.qdot);
  // A fifth row that repeats what B and E already hold (a second point of the same contact).
  Eigen::MatrixXd dependent(5, 7);
  dependent << t.j, 0.3 * t.j.row(1) - 2.0 * t.j.row(3);
  const dynamics::GeneralImpact g = dynamics::generalImpact(t.d, dependent, t.qdot);
  EXPECT_EQ(g.rank, 4);
  EXPECT_EQ(g.undetermined, 1);
  EXPECT_LT((g.qdot_plus - full.qdot_plus).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_LT((dependent * g.qdot_plus).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_LT((dependent.transpose() * g.impulses - t.d * (g.qdot_plus - t.qdot)).norm(), 1e-10);
  EXPECT_LE(kinetic(t.d, g.qdot_plus), kinetic(t.d, t.qdot));
}

// (2.72-2.74): another basis of the same constraints, T J with T invertible, and more rows
// than the chain has coordinates (Mu's three-link example, 2.79-2.82: four constraints on three
// coordinates, rank 3, the chain brought to rest).
TEST(GeneralImpact, VelocitiesDoNotDependOnTheBasisOfTheConstraints) {
  std::mt19937 rng(5);
  for (int trial = 0; trial < 20; ++trial) {
    const int n = 3 + trial % 4, m = 2 + trial % 3;
    const Eigen::MatrixXd d = randomSpd(n, rng);
    Eigen::MatrixXd j = randomMatrix(m, n, rng);
    if (trial % 2 == 0) j.row(m - 1) = 0.5 * j.row(0);  // dependent rows
    const Eigen::VectorXd qdot = randomMatrix(n, 1, rng);
    const dynamics::GeneralImpact a = dynamics::generalImpact(d, j, qdot);
    const Eigen::MatrixXd t = randomMatrix(m, m, rng) + 3 * Eigen::MatrixXd::Identity(m, m);
    const dynamics::GeneralImpact b = dynamics::generalImpact(d, t * j, qdot);
    EXPECT_EQ(a.rank, b.rank);
    EXPECT_LT((a.qdot_plus - b.qdot_plus).cwiseAbs().maxCoeff(), 1e-10) << "trial " << trial;
    EXPECT_LE(kinetic(d, a.qdot_plus), kinetic(d, qdot) + 1e-12);
  }
  const Eigen::MatrixXd d = randomSpd(3, rng);
  const dynamics::GeneralImpact rest =
      dynamics::generalImpact(d, randomMatrix(4, 3, rng), randomMatrix(3, 1, rng));
  EXPECT_EQ(rest.rank, 3);
  EXPECT_EQ(rest.undetermined, 1);
  EXPECT_LT(rest.qdot_plus.cwiseAbs().maxCoeff(), 1e-12);
}

TEST(GeneralImpact, MismatchedSizesAreRefused) {
  EXPECT_THROW(dynamics::generalImpact(Eigen::MatrixXd::Identity(3, 3), Eigen::MatrixXd::Zero(2, 4),
                                       Eigen::VectorXd::Zero(3)),
               std::invalid_argument);
}

}  // namespace
}  // namespace gaitopt::test
