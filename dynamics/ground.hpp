#pragma once
/// @file ground.hpp
/// Ground reactions and the zero-moment point. Mu gives neither formula; these are the standard
/// Newton-Euler results for the whole robot (docs/derivations.md#ground-reactions-and-the-zmp).
/// On a slope everything is in the ground frame (model.hpp), gravity model.gravityAcceleration().
#include "dynamics/kinematics.hpp"

namespace gaitopt::dynamics {

/// Ground force on the robot at the stance tip B from total linear momentum:
/// F_B = m (a_com - g_vec) - F_E, with F_E the force at E (zero in single support) [N]
/// (level ground: g_vec = -g e_y).
template <class S>
Vec2<S> stanceForce(const Model& model, const Vec<S>& theta, const Vec<S>& dtheta,
                    const Vec<S>& ddtheta, const Vec2<S>& force_swing) {
  // Scalar on the right: Eigen's nested AutoDiff types only support matrix * scalar.
  Vec2<S> f =
      pointAcceleration(model.totalComWeights(), theta, dtheta, ddtheta) * S(model.totalMass());
  const Eigen::Vector2d g_vec = model.gravityAcceleration();
  f(0) -= model.totalMass() * g_vec(0);
  f(1) -= model.totalMass() * g_vec(1);
  return f - force_swing;
}

/// x of the zero-moment point relative to B on the ground y = 0, from the rate of change of
/// angular momentum about B (Vukobratovic's definition, Mu ch. 1): with b_ci = a_ci - g_vec,
/// x_zmp = [sum m_i (b_ci,y x_ci - b_ci,x y_ci) + sum I_i omegadot_i] / sum m_i b_ci,y, with
/// omegadot_i = -ddtheta_i (theta grows clockwise) [m]. Level ground: b_ci = (xddot, yddot + g).
/// Every CoM is a weighted sum of the unit vectors u_j (Mu 2.1), so u_j and its second derivative
/// are evaluated once and weighted per link: n sines and cosines instead of 3 n^2 (the polynomial
/// gait's hip-plan search evaluates it some 9000 times).
template <class S>
S zeroMomentPoint(const Model& model, const Vec<S>& theta, const Vec<S>& dtheta,
                  const Vec<S>& ddtheta) {
  using std::cos, std::sin;
  const int n = model.nLinks();
  Mat2X<S> u(2, n), ddu(2, n);  // u_j = (sin, cos)(theta_j) and its second time derivative
  for (int j = 0; j < n; ++j) {
    const S s = sin(theta(j));
    const S c = cos(theta(j));
    const S w2 = dtheta(j) * dtheta(j);
    u.col(j) << s, c;
    ddu.col(j) << c * ddtheta(j) - s * w2, -s * ddtheta(j) - c * w2;
  }
  const Eigen::Vector2d g_vec = model.gravityAcceleration();
  S num = S(0);
  S den = S(0);
  for (int i = 0; i < n; ++i) {
    const auto& w = model.comWeights(i);
    const Vec2<S> pos = u * w.template cast<S>();
    const Vec2<S> acc = ddu * w.template cast<S>();
    const double m = model.link(i).mass;
    const S bx = acc(0) - g_vec(0);
    const S by = acc(1) - g_vec(1);
    num += m * (by * pos(0) - bx * pos(1)) - model.link(i).inertia * ddtheta(i);
    den += m * by;
  }
  return num / den;
}

}  // namespace gaitopt::dynamics
