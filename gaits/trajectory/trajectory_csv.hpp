#pragma once
/// @file trajectory_csv.hpp
/// The controller interface: trajectory.csv (docs/design.md#the-export-contract). One header
/// row, one row per sample, columns t,phase,theta1..,dtheta1..,ddtheta1..,q0..,dq0..,tau0..,
/// fb_x,fb_y,fe_x,fe_y,zmp_x,hip_x,hip_y,swing_x,swing_y,com_x,com_y, then the physical joints
/// (robots with fewer links write the columns they have). Numbers are the shortest text that reads
/// back as the same double, so a round trip is exact.
///
/// A gait folder's file holds the fixed-rate grid of grid_export.hpp (t_i = i / rate, strictly
/// increasing) and its summary.json the switch states (switch_states.hpp); files written before
/// that hold both knots of each switch at one time and end at the period. The reader takes both.
#include <string>
#include <vector>

#include "dynamics/model.hpp"
#include "gaits/trajectory/trajectory.hpp"
#include "gaits/trajectory/trajectory_text.hpp"

namespace gaitopt::gaits {

/// Writes the header and one row per row of `text`, written to a temporary name and renamed when
/// complete. @throws std::runtime_error on I/O.
void writeTrajectoryCsv(const TrajectoryText& text, const std::string& path);

/// Writes one row per knot of `rows` (derived columns q, dq, zmp, hip and swing tip computed from
/// the model; `step_length` places the leading tip for the DSP's ZMP). @throws
/// std::runtime_error on I/O, std::invalid_argument as TrajectoryText.
void writeTrajectoryCsv(const std::vector<Knot>& rows, double step_length,
                        const dynamics::Model& model, const std::string& path);

/// Reads a CSV written by writeTrajectoryCsv (or any tool following the format) for `model`, as
/// the step it was sampled from. When the summary.json beside it records switch states, they are
/// put back (joinGrid) and the step length is step_end's swing_x; otherwise the rows are the
/// knots and the step length is swing_x of the last row. @throws config::ConfigError naming the
/// file, line and column for a missing column, a wrong column count, a non-numeric or
/// non-finite value, an unknown phase, unsorted times, derived columns that disagree with the
/// angles (q != M theta beyond 1e-9), a malformed switch record, or rows that change phase with
/// no switch states to put between them.
Trajectory readTrajectoryCsv(const std::string& path, const dynamics::Model& model);

}  // namespace gaitopt::gaits
