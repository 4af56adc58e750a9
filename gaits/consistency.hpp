#pragma once
/// @file consistency.hpp
/// Checks that a trajectory is a physically valid, repeatable step: the dynamics residual at
/// every knot (the "max_defect" of summary.json) and the periodicity error after relabelling.
#include "dynamics/model.hpp"
#include "gaits/trajectory.hpp"

namespace gaitopt::gaits {

/// max over knots of |residual|_inf: SSP residual (Mu 2.7) or DSP residual (2.11 and the
/// constraint acceleration) with the knot's torques and tip force [N m].
double maxDynamicsResidual(const Trajectory& traj, const dynamics::Model& model);

/// |relabel(theta_end) - theta_start|_inf + |relabel(dtheta_end) - dtheta_start|_inf (Mu 2.38):
/// zero for a gait that repeats step after step. A step without a DSP ends at its strike, so
/// dtheta_end is taken after the single impact (Mu 2.36a, metrics.hpp touchdownImpact).
double periodicityError(const Trajectory& traj, const dynamics::Model& model);

}  // namespace gaitopt::gaits
