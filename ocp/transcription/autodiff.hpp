#pragma once
/// @file autodiff.hpp
/// Exact derivatives of a function written once as a templated functor, by forward-mode
/// automatic differentiation (Eigen's AutoDiffScalar): first order for the Jacobian, nested
/// (forward over forward) for the Hessian of lambda^T g. For small link and path functions
/// where a hand-written Hessian would be long and fragile.
///
/// The functor: template <class S> Eigen::Matrix<S, Eigen::Dynamic, 1> operator()(
///                  const Eigen::Matrix<S, Eigen::Dynamic, 1>& y) const;
///
/// Only the first `nonlinear` entries of y may enter g nonlinearly: g must be affine in the
/// others for fixed values of the first (the impact residual is linear in the rates and
/// impulses once the angles are fixed). The outer differentiation runs over those few
/// directions only, which makes the Hessian several times cheaper.
///
/// The derivative vectors have bounded sizes, so they live on the stack: with heap vectors the
/// nested impact Hessian allocated at every operation and took two thirds of the Hessian
/// callback's time in a five-link solve.
#include <Eigen/Core>
#include <unsupported/Eigen/AutoDiff>

#include "dynamics/conventions.hpp"

namespace gaitopt::ocp {

/// The most variables of one link constraint: periodicity and the double support's start take
/// two states (4 n), the impact a state and its 2 n + 6 impact variables.
inline constexpr int kMaxAdInputs = 4 * gaitopt::kMaxLinks + 8;

using AD1 = Eigen::AutoDiffScalar<Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxAdInputs, 1>>;
/// Nonlinear in at most a robot's angles.
using AD2 = Eigen::AutoDiffScalar<Eigen::Matrix<AD1, Eigen::Dynamic, 1, 0, gaitopt::kMaxLinks, 1>>;

/// d/dy_c of a first-order scalar; constants carry an empty derivative vector.
inline double adDerivative(const AD1& a, int c) {
  return c < a.derivatives().size() ? a.derivatives()(c) : 0.0;
}

/// dg/dy (rows x y.size()).
template <class Fn>
Eigen::MatrixXd adJacobian(const Fn& fn, const Eigen::VectorXd& y, int rows) {
  const int m = static_cast<int>(y.size());
  Eigen::Matrix<AD1, Eigen::Dynamic, 1> ya(m);
  for (int i = 0; i < m; ++i) ya(i) = AD1(y(i), m, i);
  const Eigen::Matrix<AD1, Eigen::Dynamic, 1> g = fn(ya);
  Eigen::MatrixXd jac(rows, m);
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < m; ++c) jac(r, c) = adDerivative(g(r), c);
  return jac;
}

/// d2 (lambda^T g) / dy2 (y.size() squared, symmetric); rows and columns past `nonlinear`
/// meet only in zeros (g affine in those entries).
template <class Fn>
Eigen::MatrixXd adHessian(const Fn& fn, const Eigen::VectorXd& y, const Eigen::VectorXd& lambda,
                          int nonlinear) {
  const int m = static_cast<int>(y.size());
  const int k = nonlinear;
  Eigen::Matrix<AD2, Eigen::Dynamic, 1> ya(m);
  for (int i = 0; i < m; ++i) {
    ya(i).value() = AD1(y(i), m, i);
    ya(i).derivatives().resize(k);
    for (int c = 0; c < k; ++c)
      ya(i).derivatives()(c) = AD1(i == c ? 1.0 : 0.0, AD1::DerType::Zero(m));
  }
  const Eigen::Matrix<AD2, Eigen::Dynamic, 1> g = fn(ya);
  AD2 s = AD2(0.0);
  for (int r = 0; r < lambda.size(); ++r) s += lambda(r) * g(r);
  Eigen::MatrixXd h = Eigen::MatrixXd::Zero(m, m);
  for (int c = 0; c < k && c < s.derivatives().size(); ++c)
    for (int d = 0; d < m; ++d) {
      h(c, d) = adDerivative(s.derivatives()(c), d);
      if (d >= k) h(d, c) = h(c, d);
    }
  return h;
}

}  // namespace gaitopt::ocp
