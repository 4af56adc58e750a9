#pragma once
/// @file computed_torque.hpp
/// Inverse dynamics on the controller's model, shared by every tracking controller
/// (tracking_controller.hpp, mu_sliding_mode.hpp):
///   SSP: tau = M^-T (D thetaddot + N) (Mu 2.43), dynamics/ssp_dynamics.hpp;
///   DSP: the torques that give the reduced coordinates p = (hip x, hip y, torso) of (2.13)/(2.21)
///        the acceleration pddot with both tips pinned, the load shared between the tips as the
///        reference shares it: the leading tip E carries the reference's force plus its share
///        (the reference's vertical share) of whatever more the model needs in total. Fixing
///        E's force absolutely made a controller whose model is 40 % heavier (Mu's case 2) put
///        all the extra weight on B through saturated ankle and knee torques; Mu's least-norm
///        torques (4.12) squeezed the tips apart (800 N of internal force).
#include "dynamics/model.hpp"
#include "gaits/trajectory/trajectory.hpp"

namespace gaitopt::sim {

/// Where a tracking controller's double-support feed-forward comes from.
enum class DspFeedForward {
  kModel,  ///< the model's computed torque for the whole acceleration
  kPlan,   ///< the reference's torques; the model's computed torque for the correction only
};

/// DSP torques (q-space) for pddot ((n-2)), given the reference's ground forces on the robot at
/// B and E [N]: [R; J] thetaddot = [pddot - Rdot thetadot; -Jdot thetadot], the total ground
/// force m (a_com + g) the model needs (dynamics/ground.hpp), E's force shared as above, then
/// D thetaddot + N = M^T tau + J^T force_e (2.11).
VecD dspComputedTorque(const dynamics::Model& model, const VecD& theta, const VecD& dtheta,
                       const VecD& pddot, const Vec2d& force_b_ref, const Vec2d& force_e_ref);

/// The DSP torques for the acceleration pddot at the knot `ref`, whose own acceleration is
/// `planned`. kModel: dspComputedTorque(pddot). kPlan: the reference's torques (computed by the
/// optimisation on the plant it was designed for) plus what the correction pddot - planned costs
/// on the model; the torques are affine in pddot at a given state, so this is
/// tau_ref + dspComputedTorque(pddot) - dspComputedTorque(planned). An error in the controller's
/// model (Mu's cases 2 and 3) then scales the correction, not the feed-forward.
VecD dspTrackingTorque(const dynamics::Model& model, const VecD& theta, const VecD& dtheta,
                       const VecD& pddot, const VecD& planned, const gaits::Knot& ref,
                       DspFeedForward dsp);

/// The torques clipped to the robot's limits; an unactuated joint gets 0 [N m].
VecD clipTorque(const dynamics::Model& model, VecD tau);

}  // namespace gaitopt::sim
