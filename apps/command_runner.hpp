#pragma once
/// @file command_runner.hpp
/// The one place that turns a subcommand's exceptions into an
/// "error: ..." line on stderr and an exit code (io/exit_code.hpp), so no bad input ever crashes
/// the tool.
#include <functional>

#include "io/exit_code.hpp"

namespace gaitopt::apps {

/// Runs `body`; prints `error: <what()>` to stderr for an exception and returns its exit code:
/// the code of a CommandError, kExitInputError for config::ConfigError, kExitInfeasible for
/// std::domain_error, kExitFailure for any other exception.
int runReportingErrors(const std::function<void()>& body);

/// For a CLI11 subcommand callback: runs `body` as runReportingErrors does and, on failure,
/// throws CLI::RuntimeError carrying the exit code (CLI::App::exit returns it silently).
void runSubcommand(const std::function<void()>& body);

}  // namespace gaitopt::apps
