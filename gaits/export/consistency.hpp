#pragma once
/// @file consistency.hpp
/// Checks that a trajectory is a physically valid, repeatable step: the dynamics residual at
/// every knot (the "max_defect" of summary.json) and the periodicity error after relabelling.
#include "dynamics/model.hpp"
#include "gaits/trajectory/trajectory.hpp"

namespace gaitopt::gaits {

/// max over knots of |residual|_inf of the equations of motion: SSP (Mu 2.7) or DSP (2.11)
/// with the knot's torques and tip force [N m].
double maxDynamicsResidual(const Trajectory& traj, const dynamics::Model& model);

/// max over DSP knots of |J ddtheta + Jdot dtheta|_inf, the acceleration of the tip E that
/// (2.9) pins (its second time derivative) [m/s^2]; 0 without a DSP.
double maxTipAcceleration(const Trajectory& traj, const dynamics::Model& model);

/// |relabel(theta_end) - theta_start|_inf + |relabel(dtheta_end) - dtheta_start|_inf (Mu 2.38):
/// zero for a gait that repeats step after step. A step without a DSP ends at its strike, so
/// dtheta_end is taken after the single impact (Mu 2.36a, metrics.hpp touchdownImpact).
double periodicityError(const Trajectory& traj, const dynamics::Model& model);

}  // namespace gaitopt::gaits
