#pragma once
/// @file ground.hpp
/// Ground reactions and the zero-moment point. Mu gives neither formula (notes/mu2004.md sec.
/// 2.5); these are the standard Newton-Euler results for the whole robot on level ground.
#include "dynamics/kinematics.hpp"

namespace gaitopt::dynamics {

/// Ground force on the robot at the stance tip B from total linear momentum:
/// F_B = m (a_com + g e_y) - F_E, with F_E the force at E (zero in single support) [N].
template <class S>
Vec2<S> stanceForce(const Model& model, const Vec<S>& theta, const Vec<S>& dtheta,
                    const Vec<S>& ddtheta, const Vec2<S>& force_swing) {
  // Scalar on the right: Eigen's nested AutoDiff types only support matrix * scalar.
  Vec2<S> f =
      pointAcceleration(model.totalComWeights(), theta, dtheta, ddtheta) * S(model.totalMass());
  f(1) += model.totalMass() * model.gravity();
  return f - force_swing;
}

/// x of the zero-moment point relative to B, from the rate of change of angular momentum about B
/// (Vukobratovic's definition, Mu ch. 1): x_zmp = [sum m_i ((yddot_ci + g) x_ci - xddot_ci y_ci)
/// + sum I_i omegadot_i] / sum m_i (yddot_ci + g), with omegadot_i = -ddtheta_i (theta grows
/// clockwise) [m].
template <class S>
S zeroMomentPoint(const Model& model, const Vec<S>& theta, const Vec<S>& dtheta,
                  const Vec<S>& ddtheta) {
  S num = S(0);
  S den = S(0);
  for (int i = 0; i < model.nLinks(); ++i) {
    const auto& w = model.comWeights(i);
    const Vec2<S> pos = pointPosition(w, theta);
    const Vec2<S> acc = pointAcceleration(w, theta, dtheta, ddtheta);
    const double m = model.link(i).mass;
    num += m * ((acc(1) + model.gravity()) * pos(0) - acc(0) * pos(1)) -
           model.link(i).inertia * ddtheta(i);
    den += m * (acc(1) + model.gravity());
  }
  return num / den;
}

/// Centre of pressure of point contacts on level ground: the x where the ground wrench has zero
/// moment. `moment_b` is the ground moment on the robot at B (ccw, = -tau0) [m].
template <class S>
S centreOfPressure(const S& x_b, const Vec2<S>& force_b, const S& moment_b, const S& x_e,
                   const Vec2<S>& force_e) {
  return (x_b * force_b(1) + x_e * force_e(1) + moment_b) / (force_b(1) + force_e(1));
}

}  // namespace gaitopt::dynamics
