#pragma once
/// @file energy.hpp
/// Energies and momenta computed link by link from CoM kinematics (Mu 2.3-2.4), deliberately not
/// from D: they are the independent formulation the tests differentiate to check D, H and G.
#include "dynamics/kinematics.hpp"

namespace gaitopt::dynamics {

/// K = sum_i 1/2 m_i |v_ci|^2 + 1/2 I_i dtheta_i^2 (Mu 2.4), with the base B moving at
/// `base_velocity` (zero when B is pinned) [J].
template <class S>
S kineticEnergy(const Model& model, const Vec<S>& theta, const Vec<S>& dtheta,
                const Vec2<S>& base_velocity = Vec2<S>::Zero()) {
  S k = S(0);
  for (int i = 0; i < model.nLinks(); ++i) {
    const Vec2<S> v = base_velocity + pointVelocity(model.comWeights(i), theta, dtheta);
    k += 0.5 * model.link(i).mass * v.squaredNorm() +
         0.5 * model.link(i).inertia * dtheta(i) * dtheta(i);
  }
  return k;
}

/// P = -sum_i m_i g_vec . r_ci with B at the origin (Mu 2.3 with gravity rotated by the slope:
/// sum_i m_i g (x_ci sin gamma + y_ci cos gamma); on level ground sum_i m_i g y_ci) [J].
template <class S>
S potentialEnergy(const Model& model, const Vec<S>& theta) {
  const Eigen::Vector2d g_vec = model.gravityAcceleration();
  S p = S(0);
  for (int i = 0; i < model.nLinks(); ++i) {
    const Vec2<S> r = pointPosition(model.comWeights(i), theta);
    p -= model.link(i).mass * (g_vec(0) * r(0) + g_vec(1) * r(1));
  }
  return p;
}

/// Total linear momentum [kg m/s].
template <class S>
Vec2<S> linearMomentum(const Model& model, const Vec<S>& theta, const Vec<S>& dtheta,
                       const Vec2<S>& base_velocity = Vec2<S>::Zero()) {
  return model.totalMass() *
         (base_velocity + pointVelocity(model.totalComWeights(), theta, dtheta));
}

/// Angular momentum about `point` (relative to B), ccw positive [kg m^2/s].
template <class S>
S angularMomentum(const Model& model, const Vec<S>& theta, const Vec<S>& dtheta,
                  const Vec2<S>& base_velocity, const Vec2<S>& point) {
  S l = S(0);
  for (int i = 0; i < model.nLinks(); ++i) {
    const Vec2<S> r = pointPosition(model.comWeights(i), theta) - point;
    const Vec2<S> v = base_velocity + pointVelocity(model.comWeights(i), theta, dtheta);
    l += model.link(i).mass * (r(0) * v(1) - r(1) * v(0)) - model.link(i).inertia * dtheta(i);
  }
  return l;
}

}  // namespace gaitopt::dynamics
