#pragma once
/// @file plot_script.hpp
/// Pictures are drawn by scripts/plots/*.py with Debian's matplotlib. A missing plotting
/// package is a warning, never a failed run. The script is started from an argument vector
/// (io/spawn.hpp): no shell sees the folder names.
#include <functional>
#include <string>
#include <vector>

namespace gaitopt::report {

/// Runs `/usr/bin/python3 scripts/plots/<script> <args...>`; prints a warning and returns false
/// when python3 or matplotlib is missing or the script fails.
bool runPlotScript(const std::string& script, const std::vector<std::string>& args);

/// The pictures of a gait folder (gait_plots.py DIR); empty when `plots` is false.
std::function<void(const std::string& dir)> gaitPictures(bool plots);

}  // namespace gaitopt::report
