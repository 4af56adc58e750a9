#pragma once
/// @file floating_base.hpp
/// The chain with a free base, q = (x_b, y_b, theta_1..theta_n): the general impact model of
/// Mu (2004) sec. 2.4 (2.47-2.62). Used where the closed forms of sec. 2.3.3 do not fit an
/// optimiser: the impact as an implicit residual in the post-impact rates and the impulses,
/// smooth in every argument. Templated on the scalar type.
#include <Eigen/Core>

#include "dynamics/kinematics.hpp"

namespace gaitopt::dynamics {

template <class S>
using MatX = Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic>;
template <class S>
using VecX = Eigen::Matrix<S, Eigen::Dynamic, 1>;

/// Jacobian of a chain point with respect to q (2 x (n + 2)): the base moves it one to one.
template <class S>
MatX<S> floatingJacobian(const ChainPoint& w, const Vec<S>& theta) {
  const auto n = theta.size();
  MatX<S> jac = MatX<S>::Zero(2, n + 2);
  jac(0, 0) = S(1.0);
  jac(1, 1) = S(1.0);
  jac.rightCols(n) = pointJacobian(w, theta);
  return jac;
}

/// D_ext(theta) = sum_i m_i J_ci^T J_ci + diag(0, 0, I_1..I_n) ((n+2) x (n+2)).
template <class S>
MatX<S> floatingBaseMassMatrix(const Model& model, const Vec<S>& theta) {
  const int n = model.nLinks();
  MatX<S> d = MatX<S>::Zero(n + 2, n + 2);
  for (int i = 0; i < n; ++i) {
    const MatX<S> jc = floatingJacobian(model.comWeights(i), theta);
    d += (jc.transpose() * jc) * S(model.link(i).mass);
    d(2 + i, 2 + i) += model.link(i).inertia;
  }
  return d;
}

/// Rigid impact at E (and at B for a double impact) as a residual (Mu 2.50, 2.57, 2.60):
///   D_ext (qdot+ - qdot-) - J_E^T P_E [- J_B^T P_B] = 0     (n + 2 rows)
///   J_E qdot+ = 0 [, J_B qdot+ = 0]                         (2 or 4 rows)
/// with qdot- = (0, 0, dtheta-) (B at rest before impact). P are impulses on the robot.
template <class S>
VecX<S> impactResidual(const Model& model, const Vec<S>& theta, const Vec<S>& dtheta_minus,
                       const VecX<S>& qdot_plus, const Vec2<S>& impulse_e,
                       const Vec2<S>* impulse_b) {
  const int n = model.nLinks();
  const Vec2<S> dbase = qdot_plus.head(2);  // B is at rest before the impact
  const Vec<S> dtheta = qdot_plus.tail(n) - dtheta_minus;
  // D_ext dq = sum_i m_i J_ci^T (J_ci dq) + I dtheta: momentum of each link, mapped back by
  // J_ci^T, without forming D_ext (n + 2 products instead of (n + 2)^2).
  VecX<S> r = VecX<S>::Zero(n + 4 + (impulse_b ? 2 : 0));
  for (int i = 0; i < n; ++i) {
    const auto& w = model.comWeights(i);
    const Vec2<S> p = (dbase + pointVelocity(w, theta, dtheta)) * S(model.link(i).mass);
    r.head(2) += p;
    r.segment(2, n) += pointJacobian(w, theta).transpose() * p;
    r(2 + i) += model.link(i).inertia * dtheta(i);
  }
  r.head(2) -= impulse_e;
  r.segment(2, n) -= pointJacobian(model.tipWeights(), theta).transpose() * impulse_e;
  r.segment(n + 2, 2) =
      qdot_plus.head(2) + pointVelocity(model.tipWeights(), theta, Vec<S>(qdot_plus.tail(n)));
  if (impulse_b) {
    r.head(2) -= *impulse_b;  // J_B = [I 0]
    r.tail(2) = qdot_plus.head(2);
  }
  return r;
}

}  // namespace gaitopt::dynamics
