#include "sim/scenario/scenario_settings.hpp"

#include <filesystem>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "config/config_error.hpp"
#include "io/data_dir.hpp"
#include "sim/contact/ground_config.hpp"
#include "sim/walk/ground_registry.hpp"

namespace gaitopt::sim {
namespace {

/// "--controller a or --controller b": the controllers for a passive stance ankle.
std::string passiveAnkleOptions() {
  std::vector<std::string> options;
  for (const ControllerEntry& c : controllers())
    if (c.passive_ankle) options.push_back("--controller " + c.name);
  return fmt::format("{}", fmt::join(options, " or "));
}

}  // namespace

std::string groundPath(const std::string& ground) {
  if (findGround(ground)) return io::dataFile(groundRecord(ground));
  // A file as the docs spell it, configs/grounds/NAME.yaml, is the shipped one where the working
  // directory has none (io::shippedIfMissing), as every other file option.
  if (const std::string file = io::shippedIfMissing(ground); std::filesystem::is_regular_file(file))
    return file;
  throw config::ConfigError(ground, "", 0,
                            fmt::format("neither a registered ground ({}) nor a ground file",
                                        fmt::join(groundNames(), ", ")));
}

std::string groundRecord(const std::string& ground) {
  return findGround(ground) ? "configs/grounds/" + ground + ".yaml" : ground;
}

namespace {
const std::vector<std::string> kFileScopes{"robot", "ground"};
}  // namespace

std::vector<config::Override> robotOverrides(const ScenarioSettings& o) {
  return config::scopedOverrides(o.sets, "robot", kFileScopes);
}

Scenario makeScenario(const ScenarioSettings& o) {
  Scenario s;
  s.controller = o.controller;
  s.steps = o.steps;
  s.ground =
      loadGround(groundPath(o.ground), config::scopedOverrides(o.sets, "ground", kFileScopes));
  s.parameter_errors = dynamics::muUncertaintyCase(o.uncertainty_case);
  s.errors_on_controller = o.uncertainty_on == "controller";
  s.mu_gains = muTable42(o.uncertainty_case);
  if (o.friction >= 0) s.friction = o.friction;
  if (o.push != 0) {
    try {
      setSweepValue(s, "push", o.push);
    } catch (const std::invalid_argument& e) {
      throw config::ConfigError("--push", "", 0, e.what());
    }
  }
  if (o.mass_error) setSweepValue(s, "mass_error", *o.mass_error);
  if (o.length_error) setSweepValue(s, "length_error", *o.length_error);
  s.gain_scale = o.gain_scale;
  s.rules = o.rules;
  // The compliant, LCP and DART grounds have their own contact laws; a restitution there was
  // recorded in summary.json and walked without.
  if (s.rules.restitution > 0 && s.ground.getIf<RigidGround>() == nullptr)
    throw config::ConfigError(
        "--restitution", "", 0,
        fmt::format("the {} ground has its own contact law: restitution applies to the rigid "
                    "ground's impacts only",
                    groundName(s.ground)));
  return s;
}

std::vector<std::string> scenarioInputs(const ScenarioSettings& o, const ReferenceFolder& ref) {
  return {ref.dir, ref.robot_path, groundPath(o.ground)};
}

void requireControllerFits(const ScenarioSettings& o, const dynamics::Model& model) {
  if (controllerEntry(o.controller).passive_ankle || model.joints().front().actuated) return;
  throw config::ConfigError(
      "--controller", o.controller, 0,
      fmt::format("the {} controller imposes all {} joint accelerations through the joint "
                  "torques, so it needs an actuated stance ankle; robot '{}' has a passive one "
                  "(walk it with {})",
                  o.controller, model.nLinks(), model.name(), passiveAnkleOptions()));
}

namespace {

nlohmann::ordered_json errorsJson(const dynamics::ParameterErrors& e) {
  return {{"mass", e.mass}, {"inertia", e.inertia}, {"length", e.length}, {"com", e.com}};
}

}  // namespace

nlohmann::ordered_json scenarioJson(const ScenarioSettings& o, const Scenario& s) {
  nlohmann::ordered_json j{{"reference", o.reference_dir},
                           {"controller", s.controller},
                           {"gain_scale", s.gain_scale},
                           {"ground", groundName(s.ground)},
                           {"ground_file", groundRecord(o.ground)},
                           {"uncertainty_case", o.uncertainty_case},
                           {"uncertainty_on", o.uncertainty_on},
                           {"parameter_errors", errorsJson(s.parameter_errors)},
                           {"push_impulse_Ns", o.push},
                           {"mu_sliding_mode",
                            {{"gains_table_4_2",
                              {{"ssp_lambda", s.mu_gains.ssp_lambda},
                               {"ssp_gamma", s.mu_gains.ssp_gamma},
                               {"ssp_sigma", s.mu_gains.ssp_sigma},
                               {"dsp_lambda", s.mu_gains.dsp_lambda},
                               {"dsp_alpha", s.mu_gains.dsp_alpha},
                               {"dsp_sigma", s.mu_gains.dsp_sigma}}},
                             {"uncertainty_bound", errorsJson(uncertaintyBound(s))},
                             {"uncertainty_side", muBoundSide(s) == BoundSide::kOverestimated
                                                      ? "model overestimates (Mu sec. 4.2)"
                                                      : "either way"}}},
                           {"steps_requested", s.steps},
                           {"contact_rules", contactRulesJson(s.rules)}};
  if (!o.sets.empty()) j["config_overrides"] = o.sets;
  return j;
}

}  // namespace gaitopt::sim
