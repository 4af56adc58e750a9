#pragma once
/// @file ssp_dynamics.hpp
/// Single-support dynamics of the pinned chain, Mu (2.7): D(theta) ddtheta + H(theta, dtheta)
/// dtheta + G(theta) = M^T tau, with D, H, G from (2.8) and the gravity sign of (2.8c)
/// corrected to G_i = -g_i sin(theta_i) (printed "+" violates energy conservation; Appendix I
/// eq. A1 has the minus; docs/derivations.md#gravity-sign). On a ground inclined by gamma
/// (model.hpp: theta from the slope normal, gravity rotated) G_i = -g_i sin(theta_i - gamma).
/// Templated on the scalar type.
#include <cmath>

#include <Eigen/Cholesky>

#include "dynamics/joint_coordinates.hpp"
#include "dynamics/model.hpp"

namespace gaitopt::dynamics {

/// D of Mu (2.8a): D_ij = p_ij cos(theta_i - theta_j), n x n, symmetric positive definite.
template <class S>
Mat<S> massMatrix(const Model& model, const Vec<S>& theta) {
  using std::cos;
  const auto& p = model.inertiaCoefficients();
  const int n = model.nLinks();
  Mat<S> d(n, n);
  for (int i = 0; i < n; ++i) {
    d(i, i) = S(p(i, i));
    for (int j = i + 1; j < n; ++j) {
      d(i, j) = p(i, j) * cos(theta(i) - theta(j));
      d(j, i) = d(i, j);
    }
  }
  return d;
}

/// C(theta, dtheta) w with H of Mu (2.8b) as a matrix, C_ij = p_ij sin(theta_i - theta_j)
/// dtheta_j (j != i), so that C dtheta is (2.8b)'s vector. With this C, Ddot - 2C is
/// skew-symmetric, the property Mu's sliding-mode proof (4.7) rests on; the sliding-mode law
/// (4.4) multiplies it by a vector other than dtheta [N m].
template <class S>
Vec<S> coriolisMatrixTimes(const Model& model, const Vec<S>& theta, const Vec<S>& dtheta,
                           const Vec<S>& w) {
  using std::sin;
  const auto& p = model.inertiaCoefficients();
  const int n = model.nLinks();
  Vec<S> h = Vec<S>::Zero(n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      if (j != i) h(i) += p(i, j) * sin(theta(i) - theta(j)) * dtheta(j) * w(j);
  return h;
}

/// H(theta, dtheta) dtheta of Mu (2.8b): (H dtheta)_i = sum_j p_ij sin(theta_i - theta_j)
/// dtheta_j^2 [N m].
template <class S>
Vec<S> coriolis(const Model& model, const Vec<S>& theta, const Vec<S>& dtheta) {
  return coriolisMatrixTimes(model, theta, dtheta, dtheta);
}

/// G of Mu (2.8c), sign corrected and with gravity rotated by the slope gamma:
/// G_i = -g_i sin(theta_i - gamma) [N m]. Derivation: with gravity (-g sin gamma, -g cos gamma)
/// in the ground frame, P = sum_i m_i g (x_ci sin gamma + y_ci cos gamma) (Mu 2.3 rotated);
/// x_ci, y_ci = sum_j w_ij (sin theta_j, cos theta_j) (2.2) give P = sum_j g_j cos(theta_j -
/// gamma), and G = dP/dtheta (Appendix I, A1).
template <class S>
Vec<S> gravityVector(const Model& model, const Vec<S>& theta) {
  using std::sin;
  const auto& g = model.gravityCoefficients();
  const double gamma = model.slope();
  Vec<S> out(model.nLinks());
  for (int i = 0; i < model.nLinks(); ++i) out(i) = -g(i) * sin(theta(i) - gamma);
  return out;
}

/// N = H dtheta + G (Mu 2.12).
template <class S>
Vec<S> nonlinearEffects(const Model& model, const Vec<S>& theta, const Vec<S>& dtheta) {
  return coriolis(model, theta, dtheta) + gravityVector(model, theta);
}

/// SSP residual of Mu (2.7) with (2.43): D ddtheta + H dtheta + G - M^T tau, n x 1 [N m].
/// Zero exactly when (theta, dtheta, ddtheta, tau) satisfy the pinned-chain dynamics.
template <class S>
Vec<S> sspResidual(const Model& model, const Vec<S>& theta, const Vec<S>& dtheta,
                   const Vec<S>& ddtheta, const Vec<S>& tau) {
  return massMatrix(model, theta) * ddtheta + nonlinearEffects(model, theta, dtheta) -
         generalizedTorque(tau);
}

/// SSP forward dynamics: ddtheta = D^-1 (M^T tau - N) [rad/s^2].
inline VecD sspForwardDynamics(const Model& model, const VecD& theta, const VecD& dtheta,
                               const VecD& tau) {
  return massMatrix(model, theta)
      .ldlt()
      .solve(generalizedTorque(tau) - nonlinearEffects(model, theta, dtheta));
}

/// SSP inverse dynamics in joint space: tau = M^-T (D ddtheta + N) (Mu 2.43) [N m].
inline VecD sspInverseDynamics(const Model& model, const VecD& theta, const VecD& dtheta,
                               const VecD& ddtheta) {
  return jointTorque<double>(massMatrix(model, theta) * ddtheta +
                             nonlinearEffects(model, theta, dtheta));
}

}  // namespace gaitopt::dynamics
