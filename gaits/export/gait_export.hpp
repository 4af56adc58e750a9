#pragma once
/// @file gait_export.hpp
/// The files of a gait folder a controller reads (docs/design.md#the-export-contract): the step on
/// one fixed-rate grid (grid_export.hpp) in trajectory.csv and trajectory.json, and summary.json
/// with the states the grid does not sample (switch_states.hpp). readTrajectoryCsv on the folder's
/// trajectory.csv gives the step back.
#include <cstddef>
#include <string>

#include <nlohmann/json.hpp>

#include "dynamics/model.hpp"
#include "gaits/trajectory/trajectory.hpp"

namespace gaitopt::gaits {

/// Writes DIR/trajectory.csv and DIR/trajectory.json (`traj` sampled at t_i = i / rate_hz) and
/// DIR/summary.json (`summary` with sample_rate_hz, phase_switches and step_end added).
/// Returns the number of samples (rows of trajectory.csv). @throws std::invalid_argument as
/// exportGrid and rowNumbers, std::runtime_error on I/O.
size_t writeGaitExport(const std::string& dir, const Trajectory& traj, const dynamics::Model& model,
                       double rate_hz, nlohmann::ordered_json summary);

}  // namespace gaitopt::gaits
