#pragma once
/// @file trajectory_csv.hpp
/// The controller interface: trajectory.csv of DESIGN.md sec. 5. One header row, one row per
/// knot, columns t,phase,theta1..,dtheta1..,ddtheta1..,q0..,dq0..,tau0..,fb_x,fb_y,fe_x,fe_y,
/// zmp_x,hip_x,hip_y,swing_x,swing_y,com_x,com_y (robots with fewer links write the columns they
/// have). Numbers are printed with 17 significant digits, so a round trip is exact.
#include <string>

#include "dynamics/model.hpp"
#include "gaits/trajectory.hpp"

namespace gaitopt::gaits {

/// Writes the CSV (derived columns q, dq, zmp, hip and swing tip computed from the model).
/// Written to a temporary name and renamed when complete. @throws std::runtime_error on I/O.
void writeTrajectoryCsv(const Trajectory& traj, const dynamics::Model& model,
                        const std::string& path);

/// Reads a CSV written by writeTrajectoryCsv (or any tool following the format) for `model`.
/// The step length is taken from swing_x of the last row. @throws config::ConfigError naming
/// the file, line and column for a missing column, a wrong column count, a non-numeric or
/// non-finite value, an unknown phase, unsorted times, or derived columns that disagree with
/// the angles (q != M theta beyond 1e-9).
Trajectory readTrajectoryCsv(const std::string& path, const dynamics::Model& model);

}  // namespace gaitopt::gaits
