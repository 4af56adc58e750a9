#pragma once
/// @file gait_summary.hpp
/// summary.json of a result folder: flat keys, SI units, fixed names
/// (docs/design.md#the-export-contract).
#include <string>

#include <nlohmann/json.hpp>

#include "dynamics/model.hpp"
#include "gaits/trajectory/trajectory.hpp"

namespace gaitopt::gaits {

/// Who made the trajectory and how (solver fields stay zero for a designed gait).
struct SummaryContext {
  std::string config;  ///< path of the gait or OCP config
  std::string status;  ///< solver status, or "designed"
  int iterations = 0;
  double wall_time_s = 0;
  double callback_time_s = 0;
  std::string cost_type = "abs_work";
};

/// Every metric of metrics.hpp and consistency.hpp, the phases, and the robot's links, joints
/// friction and slope_rad (which plots need). `cost` is the metric named by cost_type.
nlohmann::ordered_json gaitSummary(const Trajectory& traj, const dynamics::Model& model,
                                   const SummaryContext& context);

/// The key `posture_deg` of a summary: posture() of `traj` in degrees (max_torso_lean,
/// max_stance_knee_flexion, max_swing_knee_flexion).
nlohmann::ordered_json postureJson(const Trajectory& traj, const dynamics::Model& model);

/// {"heel", "toe"} of a foot [m] (0 and 0: point tips): the key `foot` of a gait's and of a walk's
/// summary, from which the pictures draw the soles.
nlohmann::ordered_json footJson(const dynamics::Foot& foot);

/// Writes JSON to path + ".tmp" and renames it when complete. @throws std::runtime_error.
void writeJsonFile(const nlohmann::ordered_json& json, const std::string& path);

}  // namespace gaitopt::gaits
