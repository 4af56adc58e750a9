#pragma once
/// @file sweep_study.hpp
/// One stability sweep (`gaitopt stability`): the values of a scenario parameter to walk, one
/// walk per value as a row of sweep_file.hpp, and the interval around the nominal value where
/// every point walks all its steps.
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "dynamics/model.hpp"
#include "gaits/impact/impact_map.hpp"
#include "sim/controllers/reference.hpp"
#include "sim/scenario/reference_folder.hpp"
#include "sim/scenario/scenario.hpp"
#include "sim/scenario/scenario_settings.hpp"
#include "sim/studies/sweep_file.hpp"

namespace gaitopt::sim {

/// axis.count values from axis.first to axis.last: evenly spaced, or by a constant ratio for a
/// geometric parameter; rounding noise below 1e-12 of the larger end snapped to 0 (so
/// -0.3:0.5:17 holds 0 rather than 5.6e-17).
/// @throws std::invalid_argument for an end outside the parameter's quantity range
///         (config/quantities.hpp), a range that does not run upwards (n >= 2 values need
///         a < b; n = 1 needs a == b), values closer than a row key's 10 digits, or a geometric
///         range whose ends are not both positive.
std::vector<double> sweepValues(const SweepParameter& parameter, const gaits::GridAxis& axis);

/// `values` (increasing) with `nominal` put in its place unless a value lies within 1e-9 of the
/// span from it or shares its row key (SweepFile::key), or it is NaN: an interval around the
/// nominal grows from a walked point, not from the grid's nearest one.
std::vector<double> withNominal(std::vector<double> values, double nominal);

/// A grid value as its row key and the CSV read it (SweepFile::key, 10 digits): 0.3, not the
/// 0.30000000000000004 of 0.2 + 0.1. What a summary reports of the grid.
double keyedValue(double value);

/// Walks `scenario` with the parameter `name` set to `value` (model: the reference's robot).
SweepRow walkSweepPoint(const dynamics::Model& model, const Reference& reference, Scenario scenario,
                        const std::string& name, double value);

/// The interval of values around `nominal` (NaN: none) where every row walks all its steps:
/// unit, meaning, geometric (spaced by a ratio), values (rows), nominal, walks_from, walks_to (null
/// when the point nearest the nominal value does not walk), and fails_below / fails_above (value,
/// failure) where the interval ends inside the rows; the ends as keyedValue gives them.
nlohmann::ordered_json walkingInterval(const SweepParameter& parameter,
                                       const std::map<std::string, SweepRow>& rows, double nominal);

/// The --set values by content, as a folder is keyed by them: key -> parsed value (numbers as
/// numbers, so 0.10 is 0.1 and 1e-3 is 0.001), the last value of a key kept, in key order unless
/// one key lies inside another's value (robot.foot and robot.foot.heel), where the order given
/// decides the result and is kept.
nlohmann::ordered_json setsContent(const std::vector<std::string>& sets);

/// What defines a sweep folder's rows (settings.json): every setting of the scenario
/// (scenarioJson: controller, gains, plant errors, push, contact rules, steps), the friction,
/// whether Poincare maps are taken, and the contents of every input file (robot, the
/// reference's trajectory.csv and summary.json, ground) by fingerprint, not by path, and the
/// --set values by content (setsContent). A rerun under other settings would mix two
/// experiments; the grid is added by the caller.
nlohmann::ordered_json sweepFolderSettings(const ScenarioSettings& settings,
                                           const ReferenceFolder& ref, const Scenario& base);

}  // namespace gaitopt::sim
