#pragma once
/// @file spawn.hpp
/// External programs (the plot scripts) started from an argument vector with posix_spawn: no
/// shell ever sees a path, so a quote or "$(...)" in a folder name is just part of the name.
#include <string>
#include <vector>

namespace gaitopt::io {

/// Which of a program's streams reach ours; the others go to /dev/null.
enum class Output {
  kAll,
  kNone,
  kErrors,  ///< stderr only: its warnings and errors, not what it lists on stdout
};

/// Runs argv[0] (an absolute path) with `argv` and waits for it. Returns its exit status, or
/// 128 + N when signal N ended it.
/// @throws std::system_error when it cannot be started (missing program, process limit).
int runProgram(const std::vector<std::string>& argv, Output output = Output::kAll);

/// runProgram with its stdout and stderr written to the file `log` (replaced), or inherited when
/// `log` is empty. An unwritable log makes the program exit 127 without running.
int runProgramInto(const std::vector<std::string>& argv, const std::string& log);

}  // namespace gaitopt::io
