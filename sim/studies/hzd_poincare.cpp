#include "sim/studies/hzd_poincare.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "dynamics/ssp_dynamics.hpp"
#include "sim/walk/hybrid_walk.hpp"

namespace gaitopt::sim {
namespace {

constexpr int kQuadratureIntervals = 2000;  // Simpson on V: error far below the fit's
constexpr double kRelativeStep = 1e-3;      // central difference in zeta

/// dzeta/dphi = I(phi) kappa(phi) on Z (file comment).
double zetaSlope(const dynamics::Model& model, const VirtualConstraints& vc, double phi) {
  const VecD theta = vc.posture(phi);
  const double inertia = stanceAngularMomentum(model, theta, vc.tangent(phi));
  return -inertia * dynamics::gravityVector<double>(model, theta).sum();
}

}  // namespace

double stanceAngularMomentum(const dynamics::Model& model, const VecD& theta, const VecD& dtheta) {
  return (dynamics::massMatrix<double>(model, theta) * dtheta).sum();
}

RestrictedMap restrictedMap(const dynamics::Model& model, const VirtualConstraints& vc) {
  RestrictedMap r{vc.phaseWeights(), vc.phaseStart(), vc.phaseEnd()};
  const double a = vc.phaseStart(), b = vc.phaseEnd();
  const double h = (b - a) / kQuadratureIntervals;
  // V by composite Simpson on pairs of intervals, keeping its running maximum.
  double v = 0, f0 = zetaSlope(model, vc, a);
  for (int i = 0; i < kQuadratureIntervals; i += 2) {
    const double x = a + i * h;
    const double f1 = zetaSlope(model, vc, x + h), f2 = zetaSlope(model, vc, x + 2 * h);
    v -= h / 3 * (f0 + 4 * f1 + f2);
    r.v_max = std::max(r.v_max, v);
    f0 = f2;
  }
  r.v_minus = v;
  const VecD theta = vc.posture(b), along = vc.tangent(b);  // phidot- = 1
  const ImpactImage image = hzdImpact(model, theta, along, vc.singleImpact());
  r.delta = stanceAngularMomentum(model, image.theta, image.dtheta) /
            stanceAngularMomentum(model, theta, along);
  r.multiplier = r.delta * r.delta;
  r.zeta_minus =
      r.multiplier < 1 ? -r.v_minus / (1 - r.multiplier) : std::numeric_limits<double>::quiet_NaN();
  r.walks = r.multiplier < 1 && r.multiplier * r.zeta_minus > r.v_max;
  if (r.zeta_minus > 0)
    r.phidot_minus = std::sqrt(2 * r.zeta_minus) / stanceAngularMomentum(model, theta, along);
  return r;
}

double restrictedReturn(const dynamics::Model& plant, const Controller& controller,
                        const Reference& ref, const VirtualConstraints& vc, double zeta_plus,
                        const EventIntegratorOptions& options) {
  const double phi = vc.phaseStart();
  const VecD theta = vc.posture(phi), along = vc.tangent(phi);
  const double phidot = std::sqrt(2 * zeta_plus) / stanceAngularMomentum(plant, theta, along);
  const StepResult step = simulateStep(plant, controller, ref, theta, along * phidot, options);
  if (!step.ok) return std::numeric_limits<double>::quiet_NaN();
  const double sigma = stanceAngularMomentum(plant, step.theta, step.dtheta);
  return sigma * sigma / 2;
}

MeasuredRestrictedMap measureRestrictedMap(const dynamics::Model& plant,
                                           const Controller& controller, const Reference& ref,
                                           const VirtualConstraints& vc, double zeta_guess,
                                           const EventIntegratorOptions& options) {
  MeasuredRestrictedMap m;
  const auto map = [&](double zeta) {
    return restrictedReturn(plant, controller, ref, vc, zeta, options);
  };
  const double dz = kRelativeStep * zeta_guess;
  const double lo = map(zeta_guess - dz), hi = map(zeta_guess + dz);
  if (!std::isfinite(lo) || !std::isfinite(hi)) {
    m.failure = "a step of the restricted map failed near the analytic fixed point";
    return m;
  }
  m.multiplier = (hi - lo) / (2 * dz);
  const double centre = (hi + lo) / 2;  // affine map: P(zeta_guess) to second order
  m.zeta_plus = zeta_guess + (centre - zeta_guess) / (1 - m.multiplier);
  m.ok = true;
  return m;
}

}  // namespace gaitopt::sim
