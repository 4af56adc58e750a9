#pragma once
/// @file plot_script.hpp
/// Pictures are drawn by plots/*.py with Debian's matplotlib. A missing plotting
/// package is a warning, never a failed run. The script is started from an argument vector
/// (io/spawn.hpp): no shell sees the folder names.
#include <functional>
#include <string>
#include <vector>

#include "io/spawn.hpp"

namespace gaitopt::report {

/// The exit status of a script that refused a malformed input file after printing one line
/// "error: <file>: <what>": EX_DATAERR of sysexits.h, which python3 itself never returns.
inline constexpr int kScriptInputError = 65;

/// Runs `/usr/bin/python3 plots/<script> <args...>` and returns its exit status, or -1
/// when python3 or matplotlib is missing or no process could be started. Prints a warning unless
/// the status is 0 or kScriptInputError (the script has said what is wrong). `output`: which of
/// the script's streams reach ours (io/spawn.hpp).
int plotScriptStatus(const std::string& script, const std::vector<std::string>& args,
                     io::Output output = io::Output::kAll);

/// plotScriptStatus() == 0: the pictures are drawn; a failure is a warning, never a failed run.
bool runPlotScript(const std::string& script, const std::vector<std::string>& args,
                   io::Output output = io::Output::kAll);

/// The pictures of a gait folder (gait_plots.py DIR); empty when `plots` is false. The folder
/// is the staging one of an io::OutputFolder, renamed when it is complete: the script's list of
/// the paths it wrote would name a folder that is gone, so only its warnings are shown, and the
/// command's last line says where the folder is.
std::function<void(const std::string& dir)> gaitPictures(bool plots);

/// What of a plot script's output reaches the user: under --quiet its errors only, else also
/// its list of the pictures it drew.
inline io::Output scriptOutput(bool quiet) {
  return quiet ? io::Output::kErrors : io::Output::kAll;
}

/// Whether `dir` holds a picture (a .png), so a command names pictures only when a script drew
/// them.
bool holdsPictures(const std::string& dir);

}  // namespace gaitopt::report
