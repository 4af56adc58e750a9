#pragma once
/// @file joint_coordinates.hpp
/// Absolute angles theta <-> relative joint angles q, and joint torques <-> generalised torques
/// (Mu 2.41-2.44). q = M theta with M lower bidiagonal: q0 = theta_1, q_j = theta_j - theta_{j+1}.
#include <Eigen/LU>

#include "dynamics/conventions.hpp"

namespace gaitopt::dynamics {

/// M of Mu (2.41), n x n.
inline MatD jointMap(int n) {
  MatD m = MatD::Zero(n, n);
  m(0, 0) = 1;
  for (int j = 1; j < n; ++j) {
    m(j, j - 1) = 1;
    m(j, j) = -1;
  }
  return m;
}

/// q = M theta (2.41); also maps rates and accelerations.
template <class S>
Vec<S> toJoint(const Vec<S>& theta) {
  Vec<S> q(theta.size());
  q(0) = theta(0);
  for (int j = 1; j < theta.size(); ++j) q(j) = theta(j - 1) - theta(j);
  return q;
}

/// theta = M^-1 q (inverse of 2.41).
template <class S>
Vec<S> toAbsolute(const Vec<S>& q) {
  Vec<S> theta(q.size());
  theta(0) = q(0);
  for (int j = 1; j < q.size(); ++j) theta(j) = theta(j - 1) - q(j);
  return theta;
}

/// Generalised torques on theta from joint torques: T_theta = M^T tau (2.42-2.43).
template <class S>
Vec<S> generalizedTorque(const Vec<S>& tau) {
  const int n = static_cast<int>(tau.size());
  Vec<S> t(n);
  t(0) = tau(0);  // the ankle acts on link 1 only; every other joint pushes two links apart
  for (int j = 1; j < n; ++j) {
    t(j - 1) += tau(j);
    t(j) = -tau(j);
  }
  return t;
}

/// Joint torques from generalised torques: tau = M^-T T_theta (inverse of 2.43).
template <class S>
Vec<S> jointTorque(const Vec<S>& t_theta) {
  const int n = static_cast<int>(t_theta.size());
  Vec<S> tau(n);
  tau(n - 1) = -t_theta(n - 1);
  for (int i = n - 2; i >= 1; --i) tau(i) = tau(i + 1) - t_theta(i);
  tau(0) = n > 1 ? S(t_theta(0) - tau(1)) : S(t_theta(0));
  return tau;
}

/// Joint-space mass matrix D_q = M^-T D M^-1 (2.44a).
inline MatD jointSpaceMassMatrix(const MatD& d) {
  const MatD m_inv = jointMap(static_cast<int>(d.rows())).inverse();
  return m_inv.transpose() * d * m_inv;
}

}  // namespace gaitopt::dynamics
