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
#include "gaits/trajectory/trajectory.hpp"
#include "gaits/trajectory/trajectory_text.hpp"

namespace gaitopt::gaits {

/// One entry per row of `text` in each column, written to a temporary name and renamed when
/// complete. @throws std::runtime_error on I/O.
void writeTrajectoryJson(const TrajectoryText& text, const std::string& path);

/// One entry per knot of `rows` in each column (`step_length` as for writeTrajectoryCsv).
/// @throws std::runtime_error on I/O, std::invalid_argument as TrajectoryText.
void writeTrajectoryJson(const std::vector<Knot>& rows, double step_length,
                         const dynamics::Model& model, const std::string& path);

}  // namespace gaitopt::gaits
