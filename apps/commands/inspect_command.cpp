#include "apps/commands/inspect_command.hpp"

#include <iostream>
#include <memory>
#include <stdexcept>

#include "apps/command_runner.hpp"
#include "apps/shipped_file.hpp"
#include "dynamics/robot_files/robot_config.hpp"
#include "gaits/trajectory/state_file.hpp"
#include "report/inspect_report.hpp"

namespace gaitopt::apps {

void runInspect(const InspectOptions& options) {
  const dynamics::Model model = dynamics::loadRobot(options.robot_path);
  const gaits::ChainState state = options.state_path
                                      ? gaits::loadState(*options.state_path, model.nLinks())
                                      : gaits::standingState(model);
  const auto report = report::inspectReport(model, state);
  std::cout << report.dump(2, ' ', false, nlohmann::ordered_json::error_handler_t::replace) << '\n'
            << std::flush;
  if (!std::cout) throw std::runtime_error("cannot write the report to stdout");
}

void registerInspectCommand(CLI::App& app) {
  auto options = std::make_shared<InspectOptions>();
  CLI::App* cmd = app.add_subcommand(
      "inspect", "Print a robot's parameters and single-support dynamics at one state as JSON");
  cmd->footer(
      "Output (stdout, JSON): robot, n_links, total_mass, gravity, friction, links, joints, "
      "state, D, H_dtheta, G, tau (SSP inverse-dynamics joint torques, Mu 2.43), "
      "kinetic_energy, potential_energy, com, swing_tip, hip (position and velocity relative "
      "to the stance tip), link_segments (each link from its proximal joint to its distal end, "
      "for stick figures). Exit codes: 0 ok, 2 bad robot/state file or usage, 1 other failure.");
  cmd->add_option("--robot", options->robot_path, "Robot YAML file (e.g. configs/robots/*.yaml)")
      ->required()
      ->transform(orShippedFile())
      ->option_text("FILE");
  cmd->add_option("--state", options->state_path,
                  "JSON state file {\"theta\":[...],\"dtheta\":[...],\"ddtheta\":[...]}: "
                  "absolute link angles [rad] in chain order, one per link; dtheta, ddtheta "
                  "optional (zero). Default: standing upright at rest (swing leg theta = pi)")
      ->transform(orShippedFile())
      ->option_text("FILE.json");
  cmd->callback([options] { runSubcommand([&] { runInspect(*options); }); });
}

}  // namespace gaitopt::apps
