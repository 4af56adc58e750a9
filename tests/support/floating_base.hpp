#pragma once
/// The chain with a free base for the tests, q = (x_b, y_b, theta_1..theta_n): mass matrix,
/// bias and tip Jacobians from the library (dynamics/floating_base_dynamics.hpp), assembled from
/// CoM Jacobians by virtual work, not from Mu's closed forms, so it is an independent check of
/// them. Contacts at B and E enter through their Jacobians and are solved as KKT systems
/// (docs/derivations.md#how-they-were-computed).
#include <utility>

#include <Eigen/Dense>

#include "dynamics/floating_base_dynamics.hpp"

namespace gaitopt::test {

using FloatingBase = dynamics::FloatingBaseDynamics;

inline FloatingBase floatingBase(const dynamics::Model& m, const VecD& theta, const VecD& dtheta) {
  return dynamics::floatingBaseDynamics(m, theta, dtheta);
}

/// Generalised force of joint torques on q: zero on the base, M^T tau on theta.
inline Eigen::VectorXd actuation(const dynamics::Model& m, const VecD& tau) {
  return dynamics::floatingBaseActuation(m, tau);
}

/// Solves mass*x = rhs + J^T f subject to J x = c (KKT). Returns (x, f).
inline std::pair<Eigen::VectorXd, Eigen::VectorXd> solveKkt(const Eigen::MatrixXd& mass,
                                                            const Eigen::VectorXd& rhs,
                                                            const Eigen::MatrixXd& jac,
                                                            const Eigen::VectorXd& c) {
  const int nq = static_cast<int>(mass.rows());
  const int nc = static_cast<int>(jac.rows());
  Eigen::MatrixXd kkt = Eigen::MatrixXd::Zero(nq + nc, nq + nc);
  kkt.topLeftCorner(nq, nq) = mass;
  kkt.topRightCorner(nq, nc) = -jac.transpose();
  kkt.bottomLeftCorner(nc, nq) = jac;
  Eigen::VectorXd b(nq + nc);
  b << rhs, c;
  const Eigen::VectorXd sol = kkt.fullPivLu().solve(b);
  return {sol.head(nq), sol.tail(nc)};
}

}  // namespace gaitopt::test
