#pragma once
/// @file tracking_controller.hpp
/// Computed-torque tracking of a reference gait on the controller's own (nominal) model: the
/// tracking law (tracking_law.hpp) sets the acceleration, inverse dynamics turns it into joint
/// torques, and the robot's torque limits clip them.
///   SSP: y = q, the relative joint angles (Mu 2.39); qddot = qddot_ref + v, torques by (2.43).
///   DSP: y = p = (hip x, hip y, torso), the reduced coordinates of (2.13)/(2.21); pddot =
///        pddot_ref + v and the tip constraint J thetaddot = -Jdot thetadot fix thetaddot; the
///        five torques then hold the reference's ground force at E (the planned load sharing),
///        from D thetaddot + N = M^T tau + J^T lambda_ref (2.11).
/// With the nominal model equal to the plant and no error, the torques are the reference's.
/// With DspFeedForward::kPlan the double support's torques are the reference's own (the plan's,
/// computed on the true model by the optimisation) plus what the model's computed torque adds for
/// the correction alone, so an error in the controller's model (Mu's cases 2 and 3) scales the
/// correction but not the feed-forward.
#include <memory>

#include "dynamics/model.hpp"
#include "gaits/trajectory/trajectory.hpp"
#include "sim/controllers/computed_torque.hpp"
#include "sim/controllers/controller.hpp"
#include "sim/controllers/tracking_law.hpp"

namespace gaitopt::sim {

class TrackingController : public Controller {
 public:
  /// @throws std::invalid_argument when the stance ankle is unactuated (computed torque needs
  ///         full actuation in single support).
  TrackingController(dynamics::Model nominal, std::shared_ptr<const TrackingLaw> law,
                     DspFeedForward dsp = DspFeedForward::kModel);

  /// Joint torques at the measured state (theta, dtheta) for reference knot `ref`.
  VecD torque(gaits::Phase phase, const VecD& theta, const VecD& dtheta, const gaits::Knot& ref,
              const Eigen::VectorXd& memory) const override;
  /// The same before clipping to the torque limits.
  VecD unclippedTorque(gaits::Phase phase, const VecD& theta, const VecD& dtheta,
                       const gaits::Knot& ref) const;

 private:
  VecD sspAcceleration(const VecD& theta, const VecD& dtheta, const gaits::Knot& ref) const;
  /// pddot of the reduced coordinates (Mu 2.21) the law asks for in the DSP: the reference's
  /// own, and the law's correction v added to it.
  struct ReducedAcceleration {
    VecD planned, correction;
  };
  ReducedAcceleration dspReducedAcceleration(const VecD& theta, const VecD& dtheta,
                                             const gaits::Knot& ref) const;
  /// The DSP's torques at the measured state (theta, dtheta).
  VecD dspTorque(const VecD& theta, const VecD& dtheta, const gaits::Knot& ref) const;

  dynamics::Model model_;
  std::shared_ptr<const TrackingLaw> law_;
  DspFeedForward dsp_;
};

}  // namespace gaitopt::sim
