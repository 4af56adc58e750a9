#pragma once
/// @file point_acceleration_derivatives.hpp
/// Exact first and second derivatives of a chain point's acceleration
///   a = sum_j w_j (ddtheta_j u'_j - dtheta_j^2 u_j),  u = (sin, cos), u' = (cos, -sin),
/// with respect to z = [theta, dtheta, ddtheta] (3n). Every term involves one link only, so the
/// Hessian is block-diagonal per link. Used by the ground-force constraints of the optimiser
/// (F_B = m (a_com + g e_y) - F_E).
#include <cmath>

#include <Eigen/Core>

#include "dynamics/model.hpp"

namespace gaitopt::dynamics {

/// da/dz (2 x 3n).
inline Eigen::MatrixXd pointAccelerationJacobian(const ChainPoint& w, const VecD& theta,
                                                 const VecD& dtheta, const VecD& ddtheta) {
  const auto n = theta.size();
  Eigen::MatrixXd jac = Eigen::MatrixXd::Zero(2, 3 * n);
  for (Eigen::Index j = 0; j < n; ++j) {
    const Eigen::Vector2d u(std::sin(theta(j)), std::cos(theta(j)));
    const Eigen::Vector2d du(std::cos(theta(j)), -std::sin(theta(j)));
    jac.col(j) = w(j) * (-ddtheta(j) * u - dtheta(j) * dtheta(j) * du);  // u'' = -u
    jac.col(n + j) = -2 * w(j) * dtheta(j) * u;
    jac.col(2 * n + j) = w(j) * du;
  }
  return jac;
}

/// d2 (c . a) / dz2 (3n x 3n, symmetric) for a weight 2-vector c.
inline Eigen::MatrixXd pointAccelerationHessian(const ChainPoint& w, const VecD& theta,
                                                const VecD& dtheta, const VecD& ddtheta,
                                                const Eigen::Vector2d& c) {
  const auto n = theta.size();
  Eigen::MatrixXd h = Eigen::MatrixXd::Zero(3 * n, 3 * n);
  for (Eigen::Index j = 0; j < n; ++j) {
    const double cu = c.dot(Eigen::Vector2d(std::sin(theta(j)), std::cos(theta(j))));
    const double cdu = c.dot(Eigen::Vector2d(std::cos(theta(j)), -std::sin(theta(j))));
    h(j, j) = w(j) * (-ddtheta(j) * cdu + dtheta(j) * dtheta(j) * cu);  // u''' = -u'
    h(j, n + j) = h(n + j, j) = -2 * w(j) * dtheta(j) * cdu;
    h(j, 2 * n + j) = h(2 * n + j, j) = -w(j) * cu;
    h(n + j, n + j) = -2 * w(j) * cu;
  }
  return h;
}

}  // namespace gaitopt::dynamics
