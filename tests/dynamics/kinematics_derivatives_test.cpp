// The kinematic primitives of dynamics/kinematics.hpp against central differences of the
// position they derive from, p = sum_j w_j u(theta_j), u = (sin, cos) (Mu 2.1, 2.2): the
// Jacobian J = dp/dtheta (2.23c), and along the motion theta(t) = theta + t dtheta (zero angular
// acceleration) Jdot = dJ/dt and the bias Jdot dtheta = d(J dtheta)/dt, the point's
// acceleration at ddtheta = 0. At random states of the shipped five-link robot, for the swing
// tip, the hip, the whole-body CoM and each link's CoM.
//
// Tolerances: a central difference misses f' by h^2/6 f'''(xi) (Taylor with remainder), and
// every derivative of p is bounded by its weights, since each term is w_j times a unit vector
// turning with theta_j. Per component:
//   J column j:    |d^3 p / d theta_j^3| <= |w_j|                -> h^2/6 |w_j|
//   Jdot column j: |d^3 J_.j / dt^3|     <= |w_j| |dtheta_j|^3   -> h^2/6 |w_j| |dtheta_j|^3
//   bias:          |d^4 p / dt^4|        <= sum_j |w_j| dtheta_j^4 -> h^2/6 sum_j |w_j| dtheta_j^4
// plus rounding, about eps |f| / h = 1e-11 at h = 1e-4, for which 1e-10 is allowed. A wrong
// sign, factor or angle in a primitive misses by O(|w| dtheta) = O(0.1), far above these bounds.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include <fmt/format.h>

#include "dynamics/kinematics.hpp"
#include "support/fixtures.hpp"

namespace gaitopt::test {
namespace {

using dynamics::ChainPoint;

constexpr double kFdStep = 1e-4;       // h of the central differences [rad, s]
constexpr double kFdRounding = 1e-10;  // allowance for eps |f| / h
constexpr int kKinematicsStates = 5;   // random states per point

struct NamedPoint {
  std::string name;
  ChainPoint w;
};

/// The points the dynamics use: E (impacts, DSP), the hip (DSP chart), the CoMs (momentum,
/// floating base).
std::vector<NamedPoint> kinematicPoints(const dynamics::Model& m) {
  std::vector<NamedPoint> points{{"swing tip", m.tipWeights()},
                                 {"hip", m.hipWeights()},
                                 {"whole-body CoM", m.totalComWeights()}};
  for (int i = 0; i < m.nLinks(); ++i) points.push_back({m.link(i).name + " CoM", m.comWeights(i)});
  return points;
}

/// Central difference of dp/dtheta_j, column by column.
Mat2Xd jacobianByDifferences(const ChainPoint& w, const VecD& theta) {
  Mat2Xd fd(2, theta.size());
  for (int j = 0; j < theta.size(); ++j) {
    const VecD step = kFdStep * VecD::Unit(theta.size(), j);
    fd.col(j) = (dynamics::pointPosition<double>(w, VecD(theta + step)) -
                 dynamics::pointPosition<double>(w, VecD(theta - step))) /
                (2 * kFdStep);
  }
  return fd;
}

class KinematicsDerivatives : public ::testing::Test {
 protected:
  dynamics::Model model_ = loadNamed("mu2004_five_link");
  std::mt19937 rng_{11};

  /// A random state: any posture, rates up to 3 rad/s (a step's swing leg turns at about that).
  std::pair<VecD, VecD> randomState() {
    const VecD theta = randomVec(rng_, model_.nLinks(), -std::numbers::pi, std::numbers::pi);
    return {theta, randomVec(rng_, model_.nLinks(), -3, 3)};
  }

  /// Checks |error| <= bound and keeps the largest error and its ratio to the bound.
  void expectWithin(double error, double bound, const std::string& where) {
    EXPECT_LE(error, bound) << where;
    worst_error_ = std::max(worst_error_, error);
    worst_ratio_ = std::max(worst_ratio_, error / bound);
  }

  void TearDown() override {
    RecordProperty("max_fd_error", fmt::format("{:.2e}", worst_error_));
    RecordProperty("max_fd_error_over_bound", fmt::format("{:.2f}", worst_ratio_));
    std::printf("largest FD error %.2e, %.2f of its bound\n", worst_error_, worst_ratio_);
  }

  double worst_error_ = 0, worst_ratio_ = 0;
};

std::string whereInTheCheck(const NamedPoint& p, int trial, int column) {
  return fmt::format("{}, trial {}, column {}", p.name, trial, column);
}

TEST_F(KinematicsDerivatives, JacobianIsTheGradientOfThePosition) {
  for (const NamedPoint& p : kinematicPoints(model_)) {
    for (int trial = 0; trial < kKinematicsStates; ++trial) {
      const VecD theta = randomState().first;
      const Mat2Xd jac = dynamics::pointJacobian<double>(p.w, theta);
      const Mat2Xd err = (jac - jacobianByDifferences(p.w, theta)).cwiseAbs();
      for (int j = 0; j < theta.size(); ++j)
        expectWithin(err.col(j).maxCoeff(), kFdStep * kFdStep / 6 * std::abs(p.w(j)) + kFdRounding,
                     whereInTheCheck(p, trial, j));
      EXPECT_GT(jac.cwiseAbs().maxCoeff(), 0.05) << p.name;  // a nonzero matrix is checked
    }
  }
}

TEST_F(KinematicsDerivatives, JacobianDotIsTheRateOfTheJacobianAlongTheMotion) {
  for (const NamedPoint& p : kinematicPoints(model_)) {
    double largest = 0;  // a nonzero Jdot is checked
    for (int trial = 0; trial < kKinematicsStates; ++trial) {
      const auto [theta, dtheta] = randomState();
      const Mat2Xd fd = (dynamics::pointJacobian<double>(p.w, VecD(theta + kFdStep * dtheta)) -
                         dynamics::pointJacobian<double>(p.w, VecD(theta - kFdStep * dtheta))) /
                        (2 * kFdStep);
      const Mat2Xd jdot = dynamics::pointJacobianDot<double>(p.w, theta, dtheta);
      const Mat2Xd err = (jdot - fd).cwiseAbs();
      for (int j = 0; j < theta.size(); ++j) {
        const double bound =
            kFdStep * kFdStep / 6 * std::abs(p.w(j)) * std::pow(std::abs(dtheta(j)), 3) +
            kFdRounding;
        expectWithin(err.col(j).maxCoeff(), bound, whereInTheCheck(p, trial, j));
      }
      largest = std::max(largest, jdot.cwiseAbs().maxCoeff());
    }
    EXPECT_GT(largest, 0.05) << p.name;
  }
}

TEST_F(KinematicsDerivatives, BiasIsTheAccelerationAtZeroAngularAcceleration) {
  for (const NamedPoint& p : kinematicPoints(model_)) {
    double largest = 0;  // a nonzero bias is checked
    for (int trial = 0; trial < kKinematicsStates; ++trial) {
      const auto [theta, dtheta] = randomState();
      // d(J dtheta)/dt with dtheta held: the point's acceleration when ddtheta = 0.
      const Vec2d fd =
          (dynamics::pointVelocity<double>(p.w, VecD(theta + kFdStep * dtheta), dtheta) -
           dynamics::pointVelocity<double>(p.w, VecD(theta - kFdStep * dtheta), dtheta)) /
          (2 * kFdStep);
      const Vec2d bias = dynamics::pointBias<double>(p.w, theta, dtheta);
      const double bound =
          kFdStep * kFdStep / 6 * p.w.cwiseAbs().dot(VecD(dtheta.array().pow(4))) + kFdRounding;
      expectWithin((bias - fd).cwiseAbs().maxCoeff(), bound,
                   fmt::format("{}, trial {}", p.name, trial));
      // Jdot dtheta is the same quantity by the other primitive.
      const Vec2d jdot_dtheta = dynamics::pointJacobianDot<double>(p.w, theta, dtheta) * dtheta;
      EXPECT_LE((bias - jdot_dtheta).cwiseAbs().maxCoeff(), 1e-12) << p.name;
      largest = std::max(largest, bias.norm());
    }
    EXPECT_GT(largest, 0.05) << p.name;
  }
}

}  // namespace
}  // namespace gaitopt::test
