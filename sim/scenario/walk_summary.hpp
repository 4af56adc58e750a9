#pragma once
/// @file walk_summary.hpp
/// summary.json of a closed-loop walk (`gaitopt simulate`): robot, the scenario's settings,
/// friction, steps_completed, fell, failure, max_tracking_error, mean step length, duration and
/// speed over the completed steps, slip per step and its largest value, the least CoP margin of
/// the stance foot and the time its ankle torque was saturated (the rules in contact_rules), the
/// deepest the rigid ground's swing tip went below the ground (max_tip_penetration_m, null on the
/// other grounds), the
/// Poincare multipliers (null when not computed, with poincare_failure when the map failed), HZD's
/// restricted Poincare map (analytic and measured) under the hzd controller, and wall_time_s.
#include <nlohmann/json.hpp>

#include "dynamics/model.hpp"
#include "sim/scenario/reference_folder.hpp"
#include "sim/scenario/scenario.hpp"
#include "sim/scenario/scenario_settings.hpp"

namespace gaitopt::sim {

/// `plant`: the model walked (the scenario's parameter errors applied).
nlohmann::ordered_json walkSummary(const ScenarioSettings& settings, const ReferenceFolder& ref,
                                   const Scenario& scenario, const dynamics::Model& plant,
                                   const ScenarioResult& result);

}  // namespace gaitopt::sim
