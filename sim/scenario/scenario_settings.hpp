#pragma once
/// @file scenario_settings.hpp
/// The settings of `gaitopt simulate` and `gaitopt stability` (which gait, controller, ground and
/// plant to walk) turned into a Scenario, the files it reads, and its record in summary.json.
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "dynamics/model.hpp"
#include "sim/contact/contact_rules.hpp"
#include "sim/scenario/reference_folder.hpp"
#include "sim/scenario/scenario.hpp"
#include "sim/walk/ground_registry.hpp"

namespace gaitopt::sim {

/// What a closed-loop command walks, as given on its command line.
struct ScenarioSettings {
  std::string reference_dir;
  std::string robot_path;                       ///< "" = from the reference's summary.json
  std::string controller = kDefaultController;  ///< a name of controllers()
  /// A name of grounds() (its configs/grounds/NAME.yaml) or a ground YAML.
  std::string ground = kDefaultGround;
  int steps = 20;
  int uncertainty_case = 1;              ///< Mu ch. 4 case
  std::string uncertainty_on = "plant";  ///< or "controller" (Mu's setting)
  double friction = -1;                  ///< < 0: the robot's
  double push = 0;  ///< horizontal hip impulse, 0.1 s pulse from mid single support of step 2 [N s]
  /// Relative errors that replace the uncertainty case's (a sweep's point walked on its own).
  std::optional<double> mass_error, length_error;
  double gain_scale = 1;
  ContactRules rules;  ///< slip, CoP and restitution settings (contact_rules.hpp)
  /// --set robot.KEY=VALUE and ground.KEY=VALUE: values of the robot and ground files.
  std::vector<std::string> sets;
};

/// The --set overrides of the robot file. @throws config::ConfigError for a key that names
/// neither the robot nor the ground file.
std::vector<config::Override> robotOverrides(const ScenarioSettings& o);

/// The ground YAML `ground` names: a registered ground's configs/grounds/<name>.yaml or a file
/// path. @throws config::ConfigError listing the registered grounds when it is neither.
std::string groundPath(const std::string& ground);

/// The ground as summary.json records it: a shipped ground by its path relative to the source
/// tree (no absolute path of the machine that ran it), a user's file as given.
std::string groundRecord(const std::string& ground);

/// The scenario the options describe. @throws config::ConfigError for a bad ground file.
Scenario makeScenario(const ScenarioSettings& o);

/// The files the scenario reads (the reference folder, the robot file it was loaded with, even
/// one found through its summary.json, and the ground file): a --out may not be, hold or lie
/// inside one of them.
std::vector<std::string> scenarioInputs(const ScenarioSettings& o, const ReferenceFolder& ref);

/// @throws config::ConfigError (exit 2) when the controller cannot drive `model`: the tracking
/// laws set every joint acceleration through the torques, so the stance ankle must be actuated
/// (unless the controller's entry, controller_registry.hpp, says it drives a passive one: HZD).
void requireControllerFits(const ScenarioSettings& o, const dynamics::Model& model);

/// The scenario's settings for summary.json.
nlohmann::ordered_json scenarioJson(const ScenarioSettings& o, const Scenario& s);

}  // namespace gaitopt::sim
