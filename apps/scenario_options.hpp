#pragma once
/// @file scenario_options.hpp
/// The command-line options shared by `gaitopt simulate` and `gaitopt stability`: which gait,
/// controller, ground and plant to walk.
#include <string>
#include <vector>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "sim/scenario.hpp"

namespace gaitopt::apps {

struct ScenarioOptions {
  std::string reference_dir;
  std::string robot_path;  ///< "" = from the reference's summary.json
  std::string controller = "computed_torque";
  std::string ground = "rigid";  ///< a shipped ground name or a ground YAML
  int steps = 20;
  int uncertainty_case = 1;              ///< Mu ch. 4 case
  std::string uncertainty_on = "plant";  ///< or "controller" (Mu's setting)
  double friction = -1;                  ///< < 0: the robot's
  double push = 0;  ///< horizontal hip impulse, 0.1 s pulse from mid single support of step 2 [N s]
  double gain_scale = 1;
};

/// Adds --reference, --robot, --controller, --ground, --steps, --uncertainty-case, --friction,
/// --push, --gain-scale and --uncertainty-on.
void addScenarioOptions(CLI::App* cmd, ScenarioOptions& o);

/// The ground YAML `ground` names: a shipped configs/grounds/<name>.yaml or a file path.
std::string groundPath(const std::string& ground);

/// The ground as summary.json records it: a shipped ground by its path relative to the source
/// tree (no absolute path of the machine that ran it), a user's file as given.
std::string groundRecord(const std::string& ground);

/// The scenario the options describe. @throws config::ConfigError for a bad ground file.
sim::Scenario makeScenario(const ScenarioOptions& o);

/// The files the scenario reads (reference folder, robot and ground files): a --out may not
/// be one of them.
std::vector<std::string> scenarioInputs(const ScenarioOptions& o);

/// @throws config::ConfigError (exit 2) when the controller cannot drive `model`: both
/// tracking laws set every joint acceleration through the torques, so the stance ankle must be
/// actuated.
void requireControllerFits(const ScenarioOptions& o, const dynamics::Model& model);

/// The scenario's settings for summary.json.
nlohmann::ordered_json scenarioJson(const ScenarioOptions& o, const sim::Scenario& s);

}  // namespace gaitopt::apps
