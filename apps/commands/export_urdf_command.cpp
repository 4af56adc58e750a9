#include "apps/commands/export_urdf_command.hpp"

#include <filesystem>
#include <memory>
#include <stdexcept>

#include <fmt/format.h>

#include "apps/command_runner.hpp"
#include "apps/shipped_file.hpp"
#include "config/config_error.hpp"
#include "dynamics/robot_files/robot_config.hpp"
#include "dynamics/robot_files/urdf_export.hpp"
#include "io/output/checked_write.hpp"

namespace gaitopt::apps {

void runExportUrdf(const ExportUrdfOptions& o) {
  // The one file this command writes: never over an input (the robot YAML).
  if (!o.out.ends_with(".urdf"))
    throw config::ConfigError(o.out, "--out", 0, "expected a .urdf file");
  if (std::filesystem::is_directory(o.out))
    throw config::ConfigError(o.out, "--out", 0, "is a folder: expected a .urdf file");
  std::error_code ec;  // a robot file named *.urdf, or a link to it
  if (std::filesystem::equivalent(o.out, o.robot_path, ec))
    throw config::ConfigError(o.out, "--out", 0,
                              "is the robot file itself (--robot): write the URDF elsewhere");
  const dynamics::Model model = dynamics::loadRobot(o.robot_path);
  std::string text;
  try {
    text = dynamics::urdfText(model, dynamics::kExportFoot);
  } catch (const std::invalid_argument& e) {
    throw config::ConfigError(o.robot_path, "name", 0, e.what());
  }
  io::writeFileAtomically(o.out, text);
  fmt::print("export-urdf: wrote {} ({} links, {} joints, feet of {} kg each)\n", o.out,
             model.nLinks() + 2, model.nLinks() + 1, dynamics::kExportFoot.mass);
}

void registerExportUrdfCommand(CLI::App& app) {
  auto options = std::make_shared<ExportUrdfOptions>();
  CLI::App* cmd =
      app.add_subcommand("export-urdf", "Write the robot as a URDF (DART, Drake, Pinocchio, ROS)");
  cmd->add_option("--robot", options->robot_path, "Robot YAML file (e.g. configs/robots/*.yaml)")
      ->required()
      ->transform(orShippedFile())
      ->option_text("FILE");
  cmd->add_option("--out", options->out, "The URDF file (written whole)")
      ->required()
      ->option_text("FILE.urdf");
  cmd->footer(fmt::format(
      "Walking plane x-z (z up), joints about y with the model's torque and rate limits; feet as\n"
      "boxes from heel to toe (spheres for point feet) of {} kg each, soles {} m below the\n"
      "tips; the root link {} has no parent joint (make it planar when loading).\n"
      "Exit codes: 0 ok, 2 bad robot file, a name a URDF cannot hold or --out not .urdf, 1 I/O.",
      dynamics::kExportFoot.mass, dynamics::kExportFoot.thickness, dynamics::kStanceFootLink));
  cmd->callback([options] { runSubcommand([&] { runExportUrdf(*options); }); });
}

}  // namespace gaitopt::apps
