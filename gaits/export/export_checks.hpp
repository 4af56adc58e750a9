#pragma once
/// @file export_checks.hpp
/// What a controller relies on in a dense export (trajectory.csv), checked on its samples
/// rather than at the solver's nodes (docs/design.md#the-optimal-control-problem): the swing tip
/// above the ground, each loaded foot's own centre of pressure on that foot, the double-support tip
/// where it was pinned, and rates that are the derivatives of the angles.
#include "dynamics/model.hpp"
#include "gaits/trajectory/trajectory.hpp"

namespace gaitopt::gaits {

/// Lowest swing-tip height over the SSP knots, in the ground frame [m] (0 at lift-off and at a
/// touchdown; negative when the tip passes below the ground).
double minSwingClearance(const Trajectory& traj, const dynamics::Model& model);

/// Smallest signed distance of the stance (trailing) foot's own centre of pressure
/// x_B = -tau0 / F_By to the ends of [-heel, toe] [m], over every knot: the ankle torque is
/// carried by foot B alone in both phases (the tip E carries no moment), so this bounds tau0
/// where the support-hull ZMP of minZmpMargin does not. Negative outside; -inf when F_By <= 0.
double minFootCopMargin(const Trajectory& traj, const dynamics::Model& model);

/// Largest |dq_j| / velocity_limit_j over the knots and the joints whose robot file gives a
/// velocity limit, with dq = M dtheta the joint rates (Mu 2.41) [-]: above 1 a joint turns
/// faster than its actuator can. 0 when no joint has a limit.
double maxJointRateUse(const Trajectory& traj, const dynamics::Model& model);

/// The same for |tau_j| / torque_limit_j [-].
double maxTorqueUse(const Trajectory& traj, const dynamics::Model& model);

/// Largest distance of the swing tip E from its pinned place (step_length, 0) over the DSP
/// knots, Mu (2.9) [m]; 0 for a step without a DSP.
double maxDspTipDrift(const Trajectory& traj, const dynamics::Model& model);

/// max_k |d theta/dt (finite differences of the angles) - dtheta_k|_inf / max_k |dtheta_k|_inf
/// over the knots with a neighbour on each side in the same phase: second-order three-point
/// differences on possibly uneven spacing [-]. Near 0 when the rates are the derivatives of
/// the angles; a few per cent when rates and angles come from different interpolants.
double maxRateMismatch(const Trajectory& traj);

/// The same for the accelerations against three-point differences of the rates, relative to
/// the largest acceleration [-]: the export's accelerations are what a computed-torque
/// controller feeds forward, so they must be the rates' derivatives too.
double maxAccelerationMismatch(const Trajectory& traj);

}  // namespace gaitopt::gaits
