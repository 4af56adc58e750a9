#pragma once
/// @file command_runner.hpp
/// Exit codes of the gaitopt tool and the one place that turns a subcommand's exceptions into an
/// "error: ..." line on stderr and an exit code, so no bad input ever crashes the tool.
#include <functional>
#include <stdexcept>
#include <string>

namespace gaitopt::apps {

/// Process exit codes shared by every subcommand.
enum ExitCode : int {
  kExitOk = 0,
  kExitFailure = 1,     ///< anything other than bad input (a bug, out of memory, stdout closed)
  kExitInputError = 2,  ///< bad command line, robot file or state file
  /// valid input describing something impossible: a leg cannot reach, or Ipopt finds the
  /// gait problem locally infeasible
  kExitInfeasible = 3,
  kExitNotConverged = 4,  ///< the solver stopped without converging (iteration limit, ...)
};

/// A failure that chooses its own exit code (e.g. a solve that did not converge).
class CommandError : public std::runtime_error {
 public:
  CommandError(ExitCode code, const std::string& message)
      : std::runtime_error(message), code_(code) {}
  ExitCode code() const { return code_; }

 private:
  ExitCode code_;
};

/// Runs `body`; prints `error: <what()>` to stderr for an exception and returns its exit code:
/// the code of a CommandError, kExitInputError for config::ConfigError, kExitInfeasible for
/// std::domain_error, kExitFailure for any other exception.
int runReportingErrors(const std::function<void()>& body);

/// For a CLI11 subcommand callback: runs `body` as runReportingErrors does and, on failure,
/// throws CLI::RuntimeError carrying the exit code (CLI::App::exit returns it silently).
void runSubcommand(const std::function<void()>& body);

}  // namespace gaitopt::apps
