#pragma once
/// @file kinematics.hpp
/// Positions, velocities, accelerations and Jacobians of points on the chain (Mu 2.1, 2.2, 2.13,
/// 2.23c), relative to the stance tip B. A point is given by its weights w (Model::tipWeights(),
/// hipWeights(), comWeights(i), totalComWeights()): position = sum_j w_j u_j with
/// u_j = (sin theta_j, cos theta_j). Templated on the scalar type for automatic differentiation.
#include <cmath>
#include <utility>

#include "dynamics/model.hpp"

namespace gaitopt::dynamics {

/// Position of a chain point relative to B [m] (Mu 2.1 / 2.2 without the x_b, y_b terms).
template <class S>
Vec2<S> pointPosition(const ChainPoint& w, const Vec<S>& theta) {
  using std::cos, std::sin;
  Vec2<S> p = Vec2<S>::Zero();
  for (int j = 0; j < theta.size(); ++j) {
    p(0) += w(j) * sin(theta(j));
    p(1) += w(j) * cos(theta(j));
  }
  return p;
}

/// Jacobian d position / d theta (2 x n); for the swing tip this is J of Mu (2.23c).
template <class S>
Mat2X<S> pointJacobian(const ChainPoint& w, const Vec<S>& theta) {
  using std::cos, std::sin;
  Mat2X<S> jac(2, theta.size());
  for (int j = 0; j < theta.size(); ++j) {
    jac(0, j) = w(j) * cos(theta(j));
    jac(1, j) = -w(j) * sin(theta(j));
  }
  return jac;
}

/// Time derivative of pointJacobian (2 x n).
template <class S>
Mat2X<S> pointJacobianDot(const ChainPoint& w, const Vec<S>& theta, const Vec<S>& dtheta) {
  using std::cos, std::sin;
  Mat2X<S> jdot(2, theta.size());
  for (int j = 0; j < theta.size(); ++j) {
    jdot(0, j) = -w(j) * sin(theta(j)) * dtheta(j);
    jdot(1, j) = -w(j) * cos(theta(j)) * dtheta(j);
  }
  return jdot;
}

/// Velocity of a chain point relative to B [m/s] (Mu 2.1 / 2.2, derivative terms).
template <class S>
Vec2<S> pointVelocity(const ChainPoint& w, const Vec<S>& theta, const Vec<S>& dtheta) {
  return pointJacobian(w, theta) * dtheta;
}

/// Jdot * dtheta of a chain point: its acceleration at zero angular acceleration [m/s^2].
template <class S>
Vec2<S> pointBias(const ChainPoint& w, const Vec<S>& theta, const Vec<S>& dtheta) {
  using std::cos, std::sin;
  Vec2<S> b = Vec2<S>::Zero();
  for (int j = 0; j < theta.size(); ++j) {
    const S w2 = w(j) * dtheta(j) * dtheta(j);
    b(0) -= w2 * sin(theta(j));
    b(1) -= w2 * cos(theta(j));
  }
  return b;
}

/// Acceleration of a chain point relative to a fixed B [m/s^2].
template <class S>
Vec2<S> pointAcceleration(const ChainPoint& w, const Vec<S>& theta, const Vec<S>& dtheta,
                          const Vec<S>& ddtheta) {
  return pointJacobian(w, theta) * ddtheta + pointBias(w, theta, dtheta);
}

/// Swing tip E relative to B (Mu 2.1).
template <class S>
Vec2<S> swingTip(const Model& model, const Vec<S>& theta) {
  return pointPosition(model.tipWeights(), theta);
}

/// Hip (distal end of the stance leg) relative to B (Mu 2.13).
template <class S>
Vec2<S> hip(const Model& model, const Vec<S>& theta) {
  return pointPosition(model.hipWeights(), theta);
}

/// Whole-body centre of mass relative to B.
template <class S>
Vec2<S> centreOfMass(const Model& model, const Vec<S>& theta) {
  return pointPosition(model.totalComWeights(), theta);
}

/// Proximal joint and distal end of link i relative to B [m]: the link's segment of a stick
/// figure (the distal end is the joint plus length * u_i, Mu 2.1).
inline std::pair<Vec2d, Vec2d> linkEnds(const Model& model, const VecD& theta, int i) {
  const Vec2d p0 = pointPosition<double>(model.jointWeights(i), theta);
  const Vec2d u(std::sin(theta(i)), std::cos(theta(i)));  // conventions.hpp
  return {p0, p0 + model.link(i).length * u};
}

}  // namespace gaitopt::dynamics
