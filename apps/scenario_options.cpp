#include "apps/scenario_options.hpp"

#include <filesystem>

#include <fmt/format.h>

#include "config/config_error.hpp"
#include "sim/ground_config.hpp"

namespace gaitopt::apps {

void addScenarioOptions(CLI::App* cmd, ScenarioOptions& o) {
  cmd->add_option("--reference", o.reference_dir,
                  "Gait result folder to track (trajectory.csv, summary.json)")
      ->required()
      ->option_text("DIR");
  cmd->add_option("--robot", o.robot_path,
                  "Robot YAML (default: configs/robots/<summary robot>.yaml)")
      ->option_text("FILE");
  cmd->add_option("--controller", o.controller, "Tracking controller")
      ->check(CLI::IsMember({"computed_torque", "sliding_mode", "hzd"}))
      ->capture_default_str();
  cmd->add_option("--ground", o.ground,
                  "rigid, impedance, lcp (configs/grounds/NAME.yaml) or a ground YAML")
      ->capture_default_str();
  cmd->add_option("--steps", o.steps, "Steps to walk")
      ->check(CLI::Range(1, 100000))
      ->capture_default_str();
  cmd->add_option("--uncertainty-case", o.uncertainty_case,
                  "Plant parameters of Mu (2004) sec. 4.3: 1 exact, 2 (+40 % m, I; +10 % l, d), "
                  "3 (+100 %, +40 %)")
      ->check(CLI::Range(1, 3))
      ->capture_default_str();
  cmd->add_option("--uncertainty-on", o.uncertainty_on,
                  "Which model the errors change: the simulated plant, or the controller's model "
                  "(Mu's setting: the gait then still fits the plant)")
      ->check(CLI::IsMember({"plant", "controller"}))
      ->capture_default_str();
  cmd->add_option("--friction", o.friction, "Ground friction coefficient (default: the robot's)")
      ->check(CLI::Range(0.0, 10.0));
  cmd->add_option(
         "--push", o.push,
         "Horizontal impulse on the hip, a 0.1 s pulse from mid single support of step 2 [N s]")
      ->check(CLI::Range(-1000.0, 1000.0))
      ->capture_default_str();
  cmd->add_option("--gain-scale", o.gain_scale, "Controller bandwidth factor (kp by s^2, kd by s)")
      ->check(CLI::Range(1e-3, 1e3))
      ->capture_default_str();
}

namespace {
bool isBuiltinGround(const std::string& ground) {
  return ground == "rigid" || ground == "impedance" || ground == "lcp";
}
}  // namespace

std::string groundPath(const std::string& ground) {
  if (isBuiltinGround(ground)) return std::string(GAITOPT_SOURCE_DIR "/") + groundRecord(ground);
  return ground;
}

std::string groundRecord(const std::string& ground) {
  return isBuiltinGround(ground) ? "configs/grounds/" + ground + ".yaml" : ground;
}

sim::Scenario makeScenario(const ScenarioOptions& o) {
  sim::Scenario s;
  s.controller = o.controller;
  s.steps = o.steps;
  s.ground = sim::loadGround(groundPath(o.ground));
  s.parameter_errors = dynamics::muUncertaintyCase(o.uncertainty_case);
  s.errors_on_controller = o.uncertainty_on == "controller";
  if (o.friction >= 0) s.friction = o.friction;
  if (o.push != 0) sim::setSweepValue(s, "push", o.push);
  s.gain_scale = o.gain_scale;
  return s;
}

std::vector<std::string> scenarioInputs(const ScenarioOptions& o) {
  return {o.reference_dir, o.robot_path, groundPath(o.ground)};
}

void requireControllerFits(const ScenarioOptions& o, const dynamics::Model& model) {
  if (model.joints().front().actuated) return;
  throw config::ConfigError(
      "--controller", o.controller, 0,
      fmt::format("the {} controller imposes all {} joint accelerations through the joint "
                  "torques, so it needs an actuated stance ankle; robot '{}' has a passive one "
                  "(walking it needs an underactuated controller, which gaitopt does not have)",
                  o.controller, model.nLinks(), model.name()));
}

nlohmann::ordered_json scenarioJson(const ScenarioOptions& o, const sim::Scenario& s) {
  return {{"reference", o.reference_dir},
          {"controller", s.controller},
          {"gain_scale", s.gain_scale},
          {"ground", sim::groundName(s.ground)},
          {"ground_file", groundRecord(o.ground)},
          {"uncertainty_case", o.uncertainty_case},
          {"uncertainty_on", o.uncertainty_on},
          {"parameter_errors",
           {{"mass", s.parameter_errors.mass},
            {"inertia", s.parameter_errors.inertia},
            {"length", s.parameter_errors.length},
            {"com", s.parameter_errors.com}}},
          {"push_impulse_Ns", o.push},
          {"steps_requested", s.steps}};
}

}  // namespace gaitopt::apps
