#pragma once
/// @file inspect_command.hpp
/// `gaitopt inspect --robot FILE [--state FILE.json]`: prints a robot's parameters and its
/// single-support dynamics at one state as JSON on stdout.
#include <optional>
#include <string>

#include <CLI/CLI.hpp>

namespace gaitopt::apps {

struct InspectOptions {
  std::string robot_path;
  std::optional<std::string> state_path;  ///< standing posture when absent
};

/// Loads the robot and state, prints the report. @throws config::ConfigError on bad input.
void runInspect(const InspectOptions& options);

/// Adds the `inspect` subcommand to `app`.
void registerInspectCommand(CLI::App& app);

}  // namespace gaitopt::apps
