#include "sim/controllers/tracking_controller.hpp"

#include <stdexcept>

#include "dynamics/dsp_dynamics.hpp"
#include "dynamics/joint_coordinates.hpp"
#include "dynamics/ssp_dynamics.hpp"
#include "sim/controllers/computed_torque.hpp"

namespace gaitopt::sim {

TrackingController::TrackingController(dynamics::Model nominal,
                                       std::shared_ptr<const TrackingLaw> law, DspFeedForward dsp)
    : model_(std::move(nominal)), law_(std::move(law)), dsp_(dsp) {
  if (!model_.joints().front().actuated)
    throw std::invalid_argument("tracking control of every joint needs an actuated stance ankle");
}

VecD TrackingController::sspAcceleration(const VecD& theta, const VecD& dtheta,
                                         const gaits::Knot& ref) const {
  using dynamics::toJoint;
  const VecD e = toJoint<double>(VecD(ref.theta)) - toJoint<double>(theta);
  const VecD edot = toJoint<double>(VecD(ref.dtheta)) - toJoint<double>(dtheta);
  const VecD qdd = toJoint<double>(VecD(ref.ddtheta)) + VecD(law_->correction(e, edot));
  return dynamics::toAbsolute<double>(qdd);
}

TrackingController::ReducedAcceleration TrackingController::dspReducedAcceleration(
    const VecD& theta, const VecD& dtheta, const gaits::Knot& ref) const {
  const auto now = dynamics::reducedCoordinates(model_, theta, dtheta);
  const auto want = dynamics::reducedCoordinates(model_, ref.theta, ref.dtheta);
  return {want.r * VecD(ref.ddtheta) + want.rdot_dth,
          law_->correction(want.p - now.p, want.r * VecD(ref.dtheta) - now.r * dtheta)};
}

VecD TrackingController::unclippedTorque(gaits::Phase phase, const VecD& theta, const VecD& dtheta,
                                         const gaits::Knot& ref) const {
  if (phase == gaits::Phase::kSsp)
    return dynamics::sspInverseDynamics(model_, theta, dtheta, sspAcceleration(theta, dtheta, ref));
  return dspTorque(theta, dtheta, ref);
}

VecD TrackingController::dspTorque(const VecD& theta, const VecD& dtheta,
                                   const gaits::Knot& ref) const {
  const ReducedAcceleration a = dspReducedAcceleration(theta, dtheta, ref);
  return dspTrackingTorque(model_, theta, dtheta, a.planned + a.correction, a.planned, ref, dsp_);
}

VecD TrackingController::torque(gaits::Phase phase, const VecD& theta, const VecD& dtheta,
                                const gaits::Knot& ref, const Eigen::VectorXd& /*memory*/) const {
  return clipTorque(model_, unclippedTorque(phase, theta, dtheta, ref));
}

}  // namespace gaitopt::sim
