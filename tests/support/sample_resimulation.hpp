#pragma once
/// @file sample_resimulation.hpp
/// The dense export's torques replayed between its samples, as a controller applies them: from
/// each sample's state the chain is integrated (chain_simulation.hpp; single support by Mu 2.7,
/// double support by the KKT dynamics of 2.11) over the interval to the next sample, with the
/// torque linear between the two samples, and the state reached is compared with the next
/// sample's. At the samples the export's torques are the inverse dynamics of its own angles, so a
/// residual there is zero by construction; this replay is not: it fails when the exported angles,
/// rates and torques between the samples do not belong to one motion of the chain (a rate that is
/// not the angles' derivative, a torque shifted by a sample, a phase's contact on the wrong tip).
/// Each interval starts from the export's own state, because the single support is unstable
/// (errors grow about 3.5 times every 0.04 s on the five-link optimum): a whole-step replay
/// would measure that instability, not the export.
#include <algorithm>
#include <vector>

#include "chain_simulation.hpp"
#include "dynamics/model.hpp"
#include "gaits/trajectory/trajectory.hpp"

namespace gaitopt::test {

struct SampleResimulation {
  /// Largest |dtheta_sim - dtheta_next| / h over the intervals: the acceleration the replay
  /// missed by, on average over the interval [rad/s^2].
  double acceleration_error = 0;
  double angle_error = 0;  ///< largest |theta_sim - theta_next| [rad]
  int intervals = 0;       ///< intervals replayed (the touchdown's is skipped: an impact)
};

/// Replays every interval between consecutive samples of one phase of `dense`.
inline SampleResimulation resimulateSamples(const gaits::Trajectory& dense,
                                            const dynamics::Model& model,
                                            double tolerance = 1e-12) {
  SampleResimulation r;
  const std::vector<gaits::Knot>& knots = dense.knots();
  for (size_t i = 0; i + 1 < knots.size(); ++i) {
    const gaits::Knot& a = knots[i];
    const gaits::Knot& b = knots[i + 1];
    const double h = b.t - a.t;
    if (a.phase != b.phase || !(h > 0)) continue;
    const auto torque = [&](double t) -> VecD { return a.tau + (b.tau - a.tau) * (t / h); };
    simulateChain(model, a.phase == gaits::Phase::kDsp, a.theta, a.dtheta, torque, {0.0, h},
                  tolerance, [&](double t, const VecD& theta, const VecD& dtheta) {
                    if (t == 0) return;
                    r.angle_error =
                        std::max(r.angle_error, (theta - b.theta).cwiseAbs().maxCoeff());
                    r.acceleration_error = std::max(r.acceleration_error,
                                                    (dtheta - b.dtheta).cwiseAbs().maxCoeff() / h);
                  });
    ++r.intervals;
  }
  return r;
}

/// The largest |ddtheta| of the export's samples [rad/s^2]: the scale of acceleration_error.
inline double peakAcceleration(const gaits::Trajectory& dense) {
  double peak = 0;
  for (const gaits::Knot& k : dense.knots()) peak = std::max(peak, k.ddtheta.cwiseAbs().maxCoeff());
  return peak;
}

}  // namespace gaitopt::test
