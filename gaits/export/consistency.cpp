#include "gaits/export/consistency.hpp"

#include <algorithm>

#include "dynamics/dsp_dynamics.hpp"
#include "dynamics/impact/relabel.hpp"
#include "gaits/export/metrics.hpp"

namespace gaitopt::gaits {

double maxDynamicsResidual(const Trajectory& traj, const dynamics::Model& model) {
  const int n = model.nLinks();
  double worst = 0;
  for (const auto& k : traj.knots()) {
    const VecD th = k.theta, dth = k.dtheta, ddth = k.ddtheta, tau = k.tau;
    const VecD r =
        k.phase == Phase::kSsp
            ? dynamics::sspResidual(model, th, dth, ddth, tau)
            : VecD(dynamics::dspResidual(model, th, dth, ddth, tau, Vec2d(k.force_swing)).head(n));
    worst = std::max(worst, r.cwiseAbs().maxCoeff());
  }
  return worst;
}

double maxTipAcceleration(const Trajectory& traj, const dynamics::Model& model) {
  const int n = model.nLinks();
  double worst = 0;
  for (const auto& k : traj.knots()) {
    if (k.phase != Phase::kDsp) continue;
    const VecD th = k.theta, dth = k.dtheta, ddth = k.ddtheta, tau = k.tau;
    const auto r = dynamics::dspResidual(model, th, dth, ddth, tau, Vec2d(k.force_swing));
    worst = std::max(worst, r.tail(r.size() - n).cwiseAbs().maxCoeff());
  }
  return worst;
}

double periodicityError(const Trajectory& traj, const dynamics::Model& model) {
  const Knot& first = traj.knots().front();
  const Knot& last = traj.knots().back();
  // An SSP-only step ends just before its strike: the next step starts after the single impact.
  VecD end_rates = last.dtheta;
  if (const auto impact = touchdownImpact(traj, model); impact && !impact->double_impact)
    end_rates = impact->dtheta_plus;
  const VecD theta = dynamics::relabelAngles<double>(model, last.theta);
  const VecD dtheta = dynamics::relabelRates<double>(end_rates);
  return (theta - VecD(first.theta)).cwiseAbs().maxCoeff() +
         (dtheta - VecD(first.dtheta)).cwiseAbs().maxCoeff();
}

}  // namespace gaitopt::gaits
