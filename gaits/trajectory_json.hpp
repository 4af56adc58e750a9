#pragma once
/// @file trajectory_json.hpp
/// trajectory.json: the same samples and columns as trajectory.csv (trajectory_columns.hpp),
/// column by column, for tools that prefer JSON:
///   {"robot": ..., "step_length": [m], "columns": [names in CSV order],
///    "data": {"t": [...], "phase": ["SSP", ...], "theta1": [...], ...}}
/// A gait folder's file holds the fixed-rate grid (grid_export.hpp); the switch states are in
/// its summary.json (switch_states.hpp).
#include <string>
#include <vector>

#include "dynamics/model.hpp"
#include "gaits/trajectory.hpp"

namespace gaitopt::gaits {

/// One entry per knot of `rows` in each column (`step_length` as for writeTrajectoryCsv).
/// Written to a temporary name and renamed when complete. @throws std::runtime_error on I/O,
/// std::invalid_argument as rowNumbers.
void writeTrajectoryJson(const std::vector<Knot>& rows, double step_length,
                         const dynamics::Model& model, const std::string& path);

}  // namespace gaitopt::gaits
