#pragma once
/// @file retime.hpp
/// A step stretched in time phase by phase: the warm start of a gait solved at another speed
/// (gait libraries). Each phase maps linearly onto its new duration, so the postures are kept
/// and the rates and accelerations scale as 1/c and 1/c^2 (c = new / old duration); torques and
/// forces are kept as they are (a guess, not a solution).
#include <vector>

#include "gaits/trajectory/trajectory.hpp"

namespace gaitopt::gaits {

/// `durations` per phase, in the order of traj.phaseDurations(); the result says it has
/// `step_length`. @throws std::invalid_argument for a count mismatch or a duration <= 0.
Trajectory retimed(const Trajectory& traj, const std::vector<double>& durations,
                   double step_length);

}  // namespace gaitopt::gaits
