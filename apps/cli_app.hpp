#pragma once
/// @file cli_app.hpp
/// The `gaitopt` command line: every subcommand registered on one CLI11 app, with the checks
/// all options share (option_checks.hpp). Used by main.cpp and by the option-parser fuzz target.
#include <CLI/CLI.hpp>

namespace gaitopt::apps {

/// Names `app` "gaitopt" and registers the subcommands, --version and the failure message.
void configureCli(CLI::App& app);

}  // namespace gaitopt::apps
