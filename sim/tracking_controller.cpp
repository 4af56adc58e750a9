#include "sim/tracking_controller.hpp"

#include <stdexcept>

#include <Eigen/Dense>

#include "dynamics/dsp_dynamics.hpp"
#include "dynamics/joint_coordinates.hpp"
#include "dynamics/kinematics.hpp"
#include "dynamics/ssp_dynamics.hpp"

namespace gaitopt::sim {

TrackingController::TrackingController(dynamics::Model nominal,
                                       std::shared_ptr<const TrackingLaw> law)
    : model_(std::move(nominal)), law_(std::move(law)) {
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

VecD TrackingController::dspAcceleration(const VecD& theta, const VecD& dtheta,
                                         const gaits::Knot& ref) const {
  const int n = model_.nLinks();
  const auto now = dynamics::reducedCoordinates(model_, theta, dtheta);
  const auto want = dynamics::reducedCoordinates(model_, ref.theta, ref.dtheta);
  const VecD pdd_ref = want.r * VecD(ref.ddtheta) + want.rdot_dth;
  const VecD pdd =
      pdd_ref + VecD(law_->correction(want.p - now.p, want.r * VecD(ref.dtheta) - now.r * dtheta));
  // [R; J] thetaddot = [pddot - Rdot thetadot; -Jdot thetadot]: n equations, n unknowns.
  const auto& tip = model_.tipWeights();
  Eigen::MatrixXd a(n, n);
  Eigen::VectorXd b(n);
  a << now.r, dynamics::pointJacobian<double>(tip, theta);
  b << pdd - now.rdot_dth, -dynamics::pointBias<double>(tip, theta, dtheta);
  return a.partialPivLu().solve(b);
}

VecD TrackingController::unclippedTorque(gaits::Phase phase, const VecD& theta, const VecD& dtheta,
                                         const gaits::Knot& ref) const {
  if (phase == gaits::Phase::kSsp)
    return dynamics::sspInverseDynamics(model_, theta, dtheta, sspAcceleration(theta, dtheta, ref));
  const VecD thdd = dspAcceleration(theta, dtheta, ref);
  const auto jac = dynamics::pointJacobian<double>(model_.tipWeights(), theta);
  const VecD generalized = dynamics::massMatrix(model_, theta) * thdd +
                           dynamics::nonlinearEffects(model_, theta, dtheta) -
                           jac.transpose() * Vec2d(ref.force_swing);
  return dynamics::jointTorque<double>(generalized);
}

VecD TrackingController::torque(gaits::Phase phase, const VecD& theta, const VecD& dtheta,
                                const gaits::Knot& ref) const {
  VecD tau = unclippedTorque(phase, theta, dtheta, ref);
  for (int j = 0; j < model_.nLinks(); ++j) {
    const auto& joint = model_.joints()[static_cast<size_t>(j)];
    const double limit = joint.actuated ? joint.torque_limit : 0.0;
    tau(j) = std::clamp(tau(j), -limit, limit);
  }
  return tau;
}

}  // namespace gaitopt::sim
