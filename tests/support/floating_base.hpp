#pragma once
/// An independent reference formulation for the tests: the chain with a free base,
/// q = (x_b, y_b, theta_1..theta_n), mass matrix (dynamics/floating_base.hpp) and forces
/// assembled from the CoM Jacobians (virtual work), not from Mu's closed forms. Contacts at B and E
/// enter through their Jacobians and are solved as KKT systems (notes/mu2004.md sec. 3.5).
#include <Eigen/Dense>

#include "dynamics/floating_base.hpp"
#include "dynamics/joint_coordinates.hpp"
#include "dynamics/kinematics.hpp"

namespace gaitopt::test {

struct FloatingBase {
  Eigen::MatrixXd mass;    ///< (n+2)^2
  Eigen::VectorXd bias;    ///< Coriolis + gravity, n+2
  Eigen::MatrixXd jac_b;   ///< 2 x (n+2), velocity of B
  Eigen::MatrixXd jac_e;   ///< 2 x (n+2), velocity of E
  Eigen::Vector2d jdot_e;  ///< Jdot_E qdot
};

inline FloatingBase floatingBase(const dynamics::Model& m, const VecD& theta, const VecD& dtheta) {
  const int n = m.nLinks();
  FloatingBase fb{Eigen::MatrixXd::Zero(n + 2, n + 2), Eigen::VectorXd::Zero(n + 2),
                  Eigen::MatrixXd::Zero(2, n + 2), Eigen::MatrixXd::Zero(2, n + 2),
                  Eigen::Vector2d::Zero()};
  fb.mass = dynamics::floatingBaseMassMatrix(m, theta);
  for (int i = 0; i < n; ++i) {
    const Eigen::MatrixXd jc = dynamics::floatingJacobian(m.comWeights(i), theta);
    const double mi = m.link(i).mass;
    const Vec2d acc_bias = dynamics::pointBias(m.comWeights(i), theta, dtheta);
    fb.bias += mi * jc.transpose() * (acc_bias + Eigen::Vector2d(0, m.gravity()));
  }
  fb.jac_b.leftCols(2).setIdentity();
  fb.jac_e.leftCols(2).setIdentity();
  fb.jac_e.rightCols(n) = dynamics::pointJacobian(m.tipWeights(), theta);
  fb.jdot_e = dynamics::pointBias(m.tipWeights(), theta, dtheta);
  return fb;
}

/// Generalised force of joint torques on q: zero on the base, M^T tau on theta.
inline Eigen::VectorXd actuation(const dynamics::Model& m, const VecD& tau) {
  Eigen::VectorXd f = Eigen::VectorXd::Zero(m.nLinks() + 2);
  f.tail(m.nLinks()) = dynamics::generalizedTorque(tau);
  return f;
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
