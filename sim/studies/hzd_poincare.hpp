#pragma once
/// @file hzd_poincare.hpp
/// The restricted Poincare map of the hybrid zero dynamics (Westervelt, Grizzle, Koditschek
/// 2003, IEEE TAC 48(1), sec. V-A, Theorem 3). On Z (y = 0, ydot = 0) the state is (phi, sigma),
/// sigma = 1^T D(theta) dtheta the angular momentum about the stance tip (the momentum
/// conjugate to a rotation of the whole chain, since D_ij depends on theta_i - theta_j only).
/// With the ankle passive, sigmadot = -sum_i G_i = sum_i g_i sin(theta_i - gamma) (Mu 2.8c),
/// and on Z sigma = I(phi) phidot with I = 1^T D(theta(phi)) dtheta/dphi, so
/// zeta = sigma^2 / 2 obeys dzeta/dphi = I(phi) kappa(phi): zeta(phi) = zeta+ - V(phi),
///   V(phi) = -int_{phi+}^{phi} I kappa.
/// The impact maps sigma- to sigma+ = delta sigma- (linear in the velocity along Z), so at the
/// section phi = phi- the restricted map is rho(zeta-) = delta^2 zeta- - V(phi-): affine, with
/// multiplier delta^2 and fixed point zeta-* = -V(phi-) / (1 - delta^2) when delta^2 < 1. The
/// walk exists when zeta+* = delta^2 zeta-* exceeds max V (phidot never vanishes).
#include <string>

#include "sim/controllers/controller.hpp"
#include "sim/controllers/hzd_virtual_constraints.hpp"
#include "sim/controllers/reference.hpp"
#include "sim/walk/event_integrator.hpp"

namespace gaitopt::sim {

/// sigma = 1^T D(theta) dtheta [kg m^2/s].
double stanceAngularMomentum(const dynamics::Model& model, const VecD& theta, const VecD& dtheta);

/// The restricted map from the zero-dynamics integral (analytic up to quadrature).
struct RestrictedMap {
  VecD phase_weights;                  ///< c of phi = c . theta (the map's coordinates)
  double phi_plus = 0, phi_minus = 0;  ///< phase after impact and at touchdown [rad]
  double delta = 0;                    ///< sigma+ / sigma- at the impact on Z
  double multiplier = 0;               ///< delta^2, the restricted map's derivative
  double v_minus = 0;                  ///< V(phi-) [(kg m^2/s)^2]
  double v_max = 0;                    ///< max of V over [phi+, phi-]
  double zeta_minus = 0;               ///< fixed point zeta-* (NaN when delta^2 >= 1)
  double phidot_minus = 0;             ///< phase rate at touchdown on the fixed point [rad/s]
  bool walks = false;                  ///< delta^2 < 1 and zeta+* > v_max
};
RestrictedMap restrictedMap(const dynamics::Model& model, const VirtualConstraints& vc);

/// The restricted map measured on the closed loop: start on Z at phi+ with zeta+ and simulate
/// one step of `plant` under `controller` (hybrid_walk.hpp), then read zeta+ of the next step.
struct MeasuredRestrictedMap {
  bool ok = false;
  std::string failure;
  double zeta_plus = 0;   ///< fixed point zeta+* of the measured map
  double multiplier = 0;  ///< its slope by central differences
};
/// zeta+ -> the next step's zeta+; NaN when the step fails.
double restrictedReturn(const dynamics::Model& plant, const Controller& controller,
                        const Reference& ref, const VirtualConstraints& vc, double zeta_plus,
                        const EventIntegratorOptions& options = {});
/// The fixed point and slope of restrictedReturn near zeta_guess (one secant step: the map is
/// affine in zeta when the closed loop stays on Z).
MeasuredRestrictedMap measureRestrictedMap(const dynamics::Model& plant,
                                           const Controller& controller, const Reference& ref,
                                           const VirtualConstraints& vc, double zeta_guess,
                                           const EventIntegratorOptions& options = {});

}  // namespace gaitopt::sim
