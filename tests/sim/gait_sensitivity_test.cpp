// The gait sensitivity norm (sim/studies/gait_sensitivity.hpp; Hobbelen and Wisse 2007) against its
// definition, the sum over steps of the indicators' squared response to a unit disturbance,
// and a scalar map whose sum is a geometric series.
#include <cmath>

#include <gtest/gtest.h>
#include <Eigen/Dense>

#include "sim/studies/gait_sensitivity.hpp"

namespace gaitopt::sim {
namespace {

/// sqrt(sum_k |e_k|^2) of indicator row i by stepping the map until the response is gone.
double summedResponse(const LinearisedGait& g, Eigen::Index i) {
  double sum = g.d.row(i).squaredNorm();
  Eigen::MatrixXd x = g.b;  // x_1 for a unit disturbance at step 0, one column per disturbance
  for (int k = 1; k < 2000; ++k) {
    sum += (g.c.row(i) * x).squaredNorm();
    x = g.a * x;
  }
  return std::sqrt(sum);
}

// x_{k+1} = a x_k + b d_k, e_k = c x_k + d d_k: e = (d, cb, cab, ca^2 b, ...), so
// GSN^2 = d^2 + c^2 b^2 / (1 - a^2). With a = 0.6, b = 2, c = 0.5, d = 0.3: 0.09 + 1 / 0.64.
TEST(GaitSensitivity, ScalarMapIsAGeometricSeries) {
  const LinearisedGait g{Eigen::MatrixXd::Constant(1, 1, 0.6), Eigen::MatrixXd::Constant(1, 1, 2),
                         Eigen::MatrixXd::Constant(1, 1, 0.5),
                         Eigen::MatrixXd::Constant(1, 1, 0.3)};
  EXPECT_NEAR(gaitSensitivity(g).norm, std::sqrt(0.09 + 1 / 0.64), 1e-14);
}

// A 3-state map with a complex pair (|lambda| = 0.9) and two indicators: the Lyapunov solution
// equals the summed response per indicator, and the total is their root sum of squares.
TEST(GaitSensitivity, EqualsTheSummedResponseOfAStableMap) {
  Eigen::MatrixXd a(3, 3);
  a << 0.9 * std::cos(0.7), -0.9 * std::sin(0.7), 0.2,  //
      0.9 * std::sin(0.7), 0.9 * std::cos(0.7), -0.1,   //
      0, 0, -0.5;
  const LinearisedGait g{a, Eigen::Vector3d(0.3, -1.2, 0.8),
                         (Eigen::MatrixXd(2, 3) << 1, 0.5, 0, 0, -2, 0.25).finished(),
                         Eigen::Vector2d(0.1, -0.4)};
  const GaitSensitivity s = gaitSensitivity(g);
  ASSERT_EQ(s.per_indicator.size(), 2);
  for (Eigen::Index i = 0; i < 2; ++i)
    EXPECT_NEAR(s.per_indicator(i), summedResponse(g, i), 1e-10 * summedResponse(g, i));
  EXPECT_NEAR(s.norm, std::hypot(summedResponse(g, 0), summedResponse(g, 1)), 1e-10 * s.norm);
}

TEST(DiscreteLyapunov, SolvesTheStepEquation) {
  Eigen::MatrixXd a(2, 2), q(2, 2);
  a << 0.5, 0.4, -0.3, 0.2;
  q << 2, 0.5, 0.5, 1;
  const Eigen::MatrixXd w = discreteLyapunov(a, q);
  EXPECT_LT((w - a.transpose() * w * a - q).cwiseAbs().maxCoeff(), 1e-14);
}

// A multiplier on the unit circle never lets the response die out: no finite norm.
TEST(GaitSensitivity, RefusesAMapThatIsNotStable) {
  const LinearisedGait g{Eigen::MatrixXd::Identity(2, 2), Eigen::MatrixXd::Ones(2, 1),
                         Eigen::MatrixXd::Ones(1, 2), Eigen::MatrixXd::Zero(1, 1)};
  EXPECT_THROW(gaitSensitivity(g), std::invalid_argument);
  const LinearisedGait wrong{Eigen::MatrixXd::Zero(2, 2), Eigen::MatrixXd::Ones(3, 1),
                             Eigen::MatrixXd::Ones(1, 2), Eigen::MatrixXd::Zero(1, 1)};
  EXPECT_THROW(gaitSensitivity(wrong), std::invalid_argument);
}

}  // namespace
}  // namespace gaitopt::sim
