#pragma once
/// @file floating_base_dynamics.hpp
/// Equations of motion of the chain with a free base, q = (x_b, y_b, theta_1..theta_n) in the
/// world frame: B = (x_b, y_b) is the stance tip (the first link's proximal end), E the swing
/// tip. Mu (2004) sec. 2.4 writes them as D(q) qddot + H qdot + G = tau (2.47) with generalised
/// contact forces Q = J^T F_e (2.50); here, by virtual work on each link CoM,
///   D_ext qddot + b(q, qdot) = M_ext^T tau + J_B^T F_B + J_E^T F_E,
///   b = sum_i m_i J_ci^T (Jdot_ci qdot - g_vec),   M_ext^T tau = (0, 0, M^T tau) (2.43),
/// where J_ci is the CoM Jacobian of link i (floating_base.hpp) and D_ext the mass matrix of
/// floatingBaseMassMatrix. b holds Coriolis, centrifugal and gravity forces: the link rotation
/// rates enter only through CoM velocities, so no term depends on the base velocity. Used by
/// the walks on compliant and time-stepping grounds, where the stance tip is not pinned. On a
/// slope the "world" frame is the ground frame of model.hpp and g_vec = gravityAcceleration().
#include <Eigen/Core>

#include "dynamics/floating_base.hpp"
#include "dynamics/joint_coordinates.hpp"

namespace gaitopt::dynamics {

/// Everything the free-base equations of motion need at one state.
struct FloatingBaseDynamics {
  Eigen::MatrixXd mass;    ///< D_ext, (n + 2) x (n + 2) [kg, kg m, kg m^2]
  Eigen::VectorXd bias;    ///< b = Coriolis + centrifugal + gravity, n + 2 [N, N m]
  Eigen::MatrixXd jac_b;   ///< 2 x (n + 2): velocity of B = jac_b qdot
  Eigen::MatrixXd jac_e;   ///< 2 x (n + 2): velocity of E = jac_e qdot
  Eigen::Vector2d jdot_e;  ///< Jdot_E qdot: acceleration of E at qddot = 0 [m/s^2]
};

/// D_ext, b and the tip Jacobians at (theta, dtheta); the base position and velocity do not
/// enter (translation invariance).
inline FloatingBaseDynamics floatingBaseDynamics(const Model& model, const VecD& theta,
                                                 const VecD& dtheta) {
  const int n = model.nLinks();
  FloatingBaseDynamics fb{floatingBaseMassMatrix(model, theta), Eigen::VectorXd::Zero(n + 2),
                          Eigen::MatrixXd::Zero(2, n + 2), Eigen::MatrixXd::Zero(2, n + 2),
                          Eigen::Vector2d::Zero()};
  const Eigen::Vector2d minus_gravity = -model.gravityAcceleration();
  for (int i = 0; i < n; ++i) {
    const Eigen::MatrixXd jc = floatingJacobian(model.comWeights(i), theta);
    const Vec2d acc_bias = pointBias(model.comWeights(i), theta, dtheta);
    fb.bias += model.link(i).mass * jc.transpose() * (acc_bias + minus_gravity);
  }
  fb.jac_b.leftCols(2).setIdentity();
  fb.jac_e = floatingJacobian(model.tipWeights(), theta);
  fb.jdot_e = pointBias(model.tipWeights(), theta, dtheta);
  return fb;
}

/// Generalised force of the joint torques on q: zero on the base, M^T tau on theta (2.43).
/// The ankle torque tau_0 acts between the ground and link 1, so it is only physical while B
/// is on the ground.
inline Eigen::VectorXd floatingBaseActuation(const Model& model, const VecD& tau) {
  Eigen::VectorXd f = Eigen::VectorXd::Zero(model.nLinks() + 2);
  f.tail(model.nLinks()) = generalizedTorque(tau);
  return f;
}

/// World position of the swing tip E: B + the chain's tip offset (Mu 2.1 with x_b, y_b) [m].
inline Eigen::Vector2d floatingSwingTip(const Model& model, const Eigen::VectorXd& q) {
  const VecD theta = q.tail(model.nLinks());
  return q.head<2>() + swingTip(model, theta);
}

/// World velocity of E: the base velocity plus the chain's (Mu 2.1 differentiated) [m/s].
inline Eigen::Vector2d floatingSwingTipVelocity(const Model& model, const Eigen::VectorXd& q,
                                                const Eigen::VectorXd& qdot) {
  const VecD theta = q.tail(model.nLinks()), dtheta = qdot.tail(model.nLinks());
  return qdot.head<2>() + pointVelocity(model.tipWeights(), theta, dtheta);
}

}  // namespace gaitopt::dynamics
