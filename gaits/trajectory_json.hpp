#pragma once
/// @file trajectory_json.hpp
/// trajectory.json: the same samples and columns as trajectory.csv (trajectory_columns.hpp),
/// column by column, for tools that prefer JSON:
///   {"robot": ..., "step_length": [m], "columns": [names in CSV order],
///    "data": {"t": [...], "phase": ["SSP", ...], "theta1": [...], ...}}
#include <string>

#include "dynamics/model.hpp"
#include "gaits/trajectory.hpp"

namespace gaitopt::gaits {

/// Written to a temporary name and renamed when complete. @throws std::runtime_error on I/O,
/// std::invalid_argument as rowNumbers.
void writeTrajectoryJson(const Trajectory& traj, const dynamics::Model& model,
                         const std::string& path);

}  // namespace gaitopt::gaits
