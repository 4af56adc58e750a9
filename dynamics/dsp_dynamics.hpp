#pragma once
/// @file dsp_dynamics.hpp
/// Double-support dynamics: the chain with both tips pinned (Mu 2.9-2.21). B is at the origin,
/// E at (L, 0) with L = step_length > 0 (E leads; before relabelling). lambda is the ground force
/// on the robot at E.
#include <Eigen/LU>

#include "dynamics/kinematics.hpp"
#include "dynamics/ssp_dynamics.hpp"

namespace gaitopt::dynamics {

/// Holonomic constraint Phi(theta) = E(theta) - (L, 0) (Mu 2.9) [m].
template <class S>
Vec2<S> dspConstraint(const Model& model, const Vec<S>& theta, double step_length) {
  Vec2<S> phi = swingTip(model, theta);
  phi(0) -= step_length;
  return phi;
}

/// DSP residual, n + 2 rows: Mu (2.11) D ddtheta + H dtheta + G - M^T tau - J^T lambda, then the
/// constraint acceleration J ddtheta + Jdot dtheta (second time derivative of 2.9).
template <class S>
VecR<S> dspResidual(const Model& model, const Vec<S>& theta, const Vec<S>& dtheta,
                    const Vec<S>& ddtheta, const Vec<S>& tau, const Vec2<S>& lambda) {
  const int n = model.nLinks();
  const Mat2X<S> jac = pointJacobian(model.tipWeights(), theta);
  VecR<S> r(n + 2);
  r.head(n) = sspResidual(model, theta, dtheta, ddtheta, tau) - jac.transpose() * lambda;
  r.tail(2) = jac * ddtheta + pointBias(model.tipWeights(), theta, dtheta);
  return r;
}

/// DSP inverse dynamics in joint space, Mu (2.11) with (2.43) solved for the torques of a
/// fully actuated chain: tau = M^-T (D ddtheta + N - J^T lambda), given the tip force lambda
/// (the DSP's torques are not unique; lambda picks one of them) [N m].
inline VecD dspInverseDynamics(const Model& model, const VecD& theta, const VecD& dtheta,
                               const VecD& ddtheta, const Vec2d& lambda) {
  const Mat2X<double> jac = pointJacobian(model.tipWeights(), theta);
  return jointTorque<double>(massMatrix(model, theta) * ddtheta +
                             nonlinearEffects(model, theta, dtheta) - jac.transpose() * lambda);
}

/// Accelerations and the ground force at E in the DSP.
struct DspSolution {
  VecD ddtheta;       ///< [rad/s^2]
  Vec2d force_swing;  ///< lambda: ground force on the robot at E [N]
};

/// Forward dynamics of (2.11) with the constraint at acceleration level, by the KKT system
/// [D -J^T; J 0] [ddtheta; lambda] = [M^T tau - N; -Jdot dtheta].
DspSolution dspForwardDynamics(const Model& model, const VecD& theta, const VecD& dtheta,
                               const VecD& tau);

/// Independent coordinates p of the DSP (Mu 2.13) generalised to any chain: hip (x, y) when the
/// legs have knees, then the torso angle when there is a torso; n - 2 of them.
struct ReducedCoordinates {
  VecD p;         ///< values
  MatD r;         ///< R = dp/dtheta ((n-2) x n)
  VecD rdot_dth;  ///< Rdot dtheta
};
ReducedCoordinates reducedCoordinates(const Model& model, const VecD& theta, const VecD& dtheta);

/// Reduced DSP model (Mu 2.19-2.21): pddot = B pdot + C (T_theta - N) and, from (2.20b),
/// lambda = -Sc2^-1 (Sa21 pdot + Sb2 (T_theta - N)).
struct ReducedDsp {
  MatD b;        ///< B ((n-2) x (n-2))
  MatD c;        ///< C ((n-2) x n), acting on generalised torques T_theta
  MatD lam_p;    ///< -Sc2^-1 Sa21 (2 x (n-2))
  Mat2Xd lam_t;  ///< -Sc2^-1 Sb2 (2 x n)
  VecD n_vec;    ///< N = H dtheta + G
  VecD pdot;     ///< R dtheta
};
/// @throws std::invalid_argument when the chain has no DSP degrees of freedom (n = 2).
ReducedDsp reducedDspModel(const Model& model, const VecD& theta, const VecD& dtheta);

}  // namespace gaitopt::dynamics
