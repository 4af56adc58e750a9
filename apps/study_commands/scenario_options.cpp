#include "apps/study_commands/scenario_options.hpp"

#include <cstdlib>
#include <map>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "apps/option_checks.hpp"
#include "apps/shipped_file.hpp"
#include "io/exit_code.hpp"
#include "sim/walk/ground_registry.hpp"

namespace gaitopt::apps {
namespace {

/// "\n  NAME: description" per registered entry, the list --help shows under an option.
template <class Entry>
std::string entryList(const std::vector<Entry>& entries) {
  std::string list;
  for (const Entry& e : entries) list += fmt::format("\n  {}: {}", e.name, e.description);
  return list;
}

/// --max-slip's range (0, 1] [m]: at 0 a tip "slid further than max_slip" at the walk's first
/// state, and every walk ended at t = 0 as a slip that its summary gave as 0.
CLI::Validator slipLimitRange() {
  return CLI::Validator(
      [](const std::string& text) {
        const double v = std::strtod(text.c_str(), nullptr);
        return v > 0 && v <= 1 ? std::string()
                               : fmt::format("expected a number in (0, 1] [m], got {}", text);
      },
      "FLOAT in (0 - 1]", "slip limit");
}

/// The failure rule of every ground (sim/contact/contact_rules.hpp).
void addContactOptions(CLI::App* cmd, sim::ContactRules& rules) {
  cmd->add_option("--max-slip", rules.max_slip,
                  "A walk fails when a tip on the ground slides further than this in one step [m]")
      ->check(slipLimitRange())
      ->capture_default_str();
  const std::map<std::string, sim::CopLimit> limits{{"saturate", sim::CopLimit::kSaturate},
                                                    {"fail", sim::CopLimit::kFail}};
  cmd->add_option("--cop-limit", rules.cop_limit,
                  "When the stance foot's CoP would leave [-heel, toe]: saturate the ankle torque, "
                  "or fail as a foot rotation")
      ->transform(CLI::CheckedTransformer(limits))
      ->default_str("saturate");
  cmd->add_option("--restitution", rules.restitution,
                  "Newton restitution e_n of rigid-ground impacts (0: plastic; rigid ground "
                  "only). A landing tip that rebounds ends the walk: a rebound is not modelled")
      ->check(CLI::Range(0.0, 1.0))
      ->capture_default_str();
}

}  // namespace

void addScenarioOptions(CLI::App* cmd, sim::ScenarioSettings& o) {
  cmd->add_option("--reference", o.reference_dir,
                  "Gait result folder to track (trajectory.csv, summary.json)")
      ->required()
      ->option_text("DIR");
  cmd->add_option("--robot", o.robot_path,
                  "Robot YAML (default: configs/robots/<summary robot>.yaml)")
      ->transform(orShippedFile())
      ->option_text("FILE");
  cmd->add_option("--controller", o.controller,
                  "Controller, one of:" + entryList(sim::controllers()))
      ->check(CLI::IsMember(sim::controllerNames()))
      ->capture_default_str();
  cmd->add_option(
         "--ground", o.ground,
         "Ground: a ground YAML or one of (configs/grounds/NAME.yaml):" + entryList(sim::grounds()))
      ->capture_default_str();
  cmd->add_option("--steps", o.steps, "Steps to walk")
      ->check(quantityRange(config::kSteps))
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
  cmd->add_option("--mass-error", o.mass_error,
                  "Relative error of the masses and inertias (replaces the case's; a sweep's "
                  "mass_error point)")
      ->check(quantityRange(config::kMassError));
  cmd->add_option("--length-error", o.length_error,
                  "Relative error of the lengths and CoM offsets (replaces the case's)")
      ->check(quantityRange(config::kLengthError));
  cmd->add_option("--friction", o.friction, "Ground friction coefficient (default: the robot's)")
      ->check(quantityRange(config::kFriction));
  cmd->add_option(
         "--push", o.push,
         "Horizontal impulse on the hip, a 0.1 s pulse from mid single support of step 2 [N s]")
      ->check(quantityRange(config::kPush))
      ->capture_default_str();
  cmd->add_option("--gain-scale", o.gain_scale, "Controller bandwidth factor (kp by s^2, kd by s)")
      ->check(quantityRange(config::kGainScale))
      ->capture_default_str();
  cmd->add_option("--set", o.sets,
                  "Replace one value of the robot or ground file, e.g. --set robot.foot.heel=0.1 "
                  "or --set ground.time_step=0.001 (repeatable; checked as the file is, recorded "
                  "in summary.json)")
      ->option_text("robot.KEY=VALUE|ground.KEY=VALUE");
  addContactOptions(cmd, o.rules);
}

void checkControllerFitsReference(const sim::ReferenceFolder& ref, const sim::Reference& reference,
                                  const sim::Scenario& scenario) {
  try {
    sim::makeController(sim::scenarioControllerModel(ref.model, scenario), reference, scenario);
  } catch (const std::invalid_argument& e) {
    throw io::CommandError(
        io::kExitInputError,
        fmt::format("--controller {}: {}: {}", scenario.controller, ref.dir, e.what()));
  }
}

}  // namespace gaitopt::apps
