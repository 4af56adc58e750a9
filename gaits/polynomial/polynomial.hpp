#pragma once
/// @file polynomial.hpp
/// Univariate polynomials in time with their derivatives, and the boundary-value fits the
/// polynomial gait of Mu (2004) ch. 3 needs.
#include <Eigen/Core>

namespace gaitopt::gaits {

/// p(t) = sum_k c_k t^k.
class Polynomial {
 public:
  Polynomial() = default;
  explicit Polynomial(Eigen::VectorXd coefficients) : c_(std::move(coefficients)) {}

  /// d^order p / dt^order at t (order 0, 1, 2, ...).
  double operator()(double t, int order = 0) const;
  const Eigen::VectorXd& coefficients() const { return c_; }

 private:
  Eigen::VectorXd c_;
};

/// Cubic with p(0) = x0, p'(0) = v0, p(T) = x1, p'(T) = v1 (Hermite form of Mu 3.13 with the
/// conditions 3.16-3.23).
Polynomial hermiteCubic(double x0, double v0, double x1, double v1, double duration);

/// Quintic through six conditions: values and first derivatives at the given times (a linear
/// solve, used for y_a of Mu 3.1 with 3.2, 3.3, 3.5, 3.6, 3.10, 3.12).
/// @param times  three times; @param values, slopes at those times.
Polynomial quinticThrough(const Eigen::Vector3d& times, const Eigen::Vector3d& values,
                          const Eigen::Vector3d& slopes);

}  // namespace gaitopt::gaits
