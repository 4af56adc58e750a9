#pragma once
/// @file exit_code.hpp
/// The exit codes of the gaitopt tool (docs/design.md#output-folders-and-failures), shared by the
/// command line and the Python module's exceptions, and the failure that chooses its own code.
#include <stdexcept>
#include <string>

namespace gaitopt::io {

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

/// A failure that chooses its own exit code (e.g. a solve that did not converge). An empty
/// message: the failure has been reported already, by the program that found it.
class CommandError : public std::runtime_error {
 public:
  CommandError(ExitCode code, const std::string& message)
      : std::runtime_error(message), code_(code) {}
  ExitCode code() const { return code_; }

 private:
  ExitCode code_;
};

}  // namespace gaitopt::io
