#pragma once
/// @file switch_states.hpp
/// The states a fixed-rate export does not sample (grid_export.hpp), kept in summary.json so
/// nothing is lost:
///   "sample_rate_hz": rate of trajectory.csv [Hz],
///   "phase_switches": [{"t": [s], "from": "SSP", "to": "DSP",
///                       "before": ROW, "after": ROW}, ...],
///   "step_end": ROW (the state at t = duration, the end of the step)
/// where ROW is one row of trajectory.csv as an object, column name -> value, every column of
/// trajectory_columns.hpp ("t", "phase", "theta1", ...). "before" is the pre-impact state (the
/// last of the SSP), "after" the post-impact one (Mu 2.23-2.30; equal rates for a touchdown at
/// rest), so a reader rebuilds the step with both knots of the switch at one time.
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "dynamics/model.hpp"
#include "gaits/trajectory/grid_export.hpp"
#include "gaits/trajectory/trajectory_row.hpp"

namespace gaitopt::gaits {

/// sample_rate_hz, phase_switches and step_end of `grid` (numbers exact: JSON keeps 17 digits).
/// @throws std::invalid_argument as rowNumbers.
nlohmann::ordered_json switchStatesJson(const GridExport& grid, const dynamics::Model& model);

/// The switch states of a summary.json, read back.
struct SwitchStates {
  double rate_hz = 0;  ///< sample_rate_hz
  std::vector<PhaseSwitch> switches;
  Row end;  ///< its swing_x is the step length
};

/// The switch states recorded in the summary.json at `path`; nullopt when there is no such file
/// or it has no "phase_switches" (a folder written before the fixed-rate grid, whose CSV still
/// holds both switch knots and ends at the period). @throws config::ConfigError naming the key
/// for a malformed record (as parseRow, and a switch that is not SSP -> DSP at one time).
std::optional<SwitchStates> readSwitchStates(const std::string& path, const dynamics::Model& model);

}  // namespace gaitopt::gaits
