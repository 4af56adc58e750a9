// The autodiff link constraints (ocp/transcription/autodiff.hpp) keep their derivative vectors on
// the stack, bounded by kMaxAdInputs variables and kMaxLinks nonlinear ones: at the bounds the
// derivatives are exact, and a constraint past them is refused when built rather than overrunning
// memory.
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "ocp/transcription/autodiff_constraint.hpp"

namespace gaitopt::ocp {
namespace {

/// g0 = sum_i y_i sin(y_0 + ... ): nonlinear in the first k entries, affine in the rest, with
/// every variable present; g1 = y_0 y_1 + y_last.
struct Mixed {
  int k;
  template <class S>
  Eigen::Matrix<S, Eigen::Dynamic, 1> operator()(
      const Eigen::Matrix<S, Eigen::Dynamic, 1>& y) const {
    using std::sin;
    S angle = S(0.0);
    for (int i = 0; i < k; ++i) angle += y(i);
    Eigen::Matrix<S, Eigen::Dynamic, 1> g(2);
    g(0) = S(0.0);
    for (Eigen::Index i = 0; i < y.size(); ++i) g(0) += y(i) * sin(angle);
    g(1) = y(0) * y(1) + y(y.size() - 1);
    return g;
  }
};

TEST(AutoDiff, DerivativesAreExactAtTheSizeBounds) {
  const int m = kMaxAdInputs, k = kMaxLinks;
  const Eigen::VectorXd y = Eigen::VectorXd::LinSpaced(m, -0.4, 0.7);
  const Eigen::Vector2d lambda(0.3, -1.7);
  const double angle = y.head(k).sum(), sum = y.sum();
  const Eigen::MatrixXd jac = adJacobian(Mixed{k}, y, 2);
  const Eigen::MatrixXd hess = adHessian(Mixed{k}, y, lambda, k);
  for (int i = 0; i < m; ++i) {
    // d g0 / dy_i = sin(angle) + [i < k] sum cos(angle)
    EXPECT_NEAR(jac(0, i), std::sin(angle) + (i < k ? sum * std::cos(angle) : 0.0), 1e-12);
    for (int j = 0; j <= i; ++j) {
      // d2 g0 / dy_i dy_j = [i < k] cos + [j < k] cos - [i, j < k] sum sin
      const double g0 = (i < k ? std::cos(angle) : 0.0) + (j < k ? std::cos(angle) : 0.0) -
                        (i < k && j < k ? sum * std::sin(angle) : 0.0);
      const double g1 = (i == 1 && j == 0) ? 1.0 : 0.0;
      EXPECT_NEAR(hess(i, j), lambda(0) * g0 + lambda(1) * g1, 1e-12) << i << ", " << j;
      EXPECT_EQ(hess(i, j), hess(j, i));
    }
  }
  EXPECT_EQ(jac(1, m - 1), 1.0);
}

TEST(AutoDiff, ConstraintPastTheBoundsIsRefusedByName) {
  std::vector<int> indices(kMaxAdInputs + 1);
  std::iota(indices.begin(), indices.end(), 0);
  const auto build = [&](std::vector<int> idx, int nonlinear) {
    return AutoDiffConstraint<Mixed>("too_wide", 2, std::move(idx), nonlinear, Mixed{1},
                                     Eigen::VectorXd::Zero(2), Eigen::VectorXd::Zero(2));
  };
  try {
    build(indices, 1);
    FAIL() << "built";
  } catch (const std::logic_error& e) {
    EXPECT_NE(std::string(e.what()).find("too_wide"), std::string::npos) << e.what();
  }
  indices.pop_back();
  EXPECT_NO_THROW(build(indices, kMaxLinks));
  EXPECT_THROW(build(indices, kMaxLinks + 1), std::logic_error);
}

}  // namespace
}  // namespace gaitopt::ocp
