#pragma once
/// @file export_urdf_command.hpp
/// `gaitopt export-urdf --robot FILE --out FILE.urdf`: the robot as a URDF for DART, Drake,
/// Pinocchio and ROS tools (dynamics/robot_files/urdf_export.hpp: frames, feet, the planar root).
#include <string>

#include <CLI/CLI.hpp>

namespace gaitopt::apps {

struct ExportUrdfOptions {
  std::string robot_path;
  std::string out;  ///< a .urdf file
};

/// Loads the robot and writes its URDF whole (atomically).
/// @throws config::ConfigError on a bad robot file, a name a URDF cannot hold, or an --out that is
///         not a .urdf file; io::WriteError when the file cannot be written.
void runExportUrdf(const ExportUrdfOptions& options);

/// Adds the `export-urdf` subcommand to `app`.
void registerExportUrdfCommand(CLI::App& app);

}  // namespace gaitopt::apps
