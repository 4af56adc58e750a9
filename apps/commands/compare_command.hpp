#pragma once
/// @file compare_command.hpp
/// `gaitopt compare A B --out DIR`: two gait result folders side by side. DIR/comparison.md holds
/// the table (energy, cost of transport, torque-squared integral, peak torque per joint, min
/// normal force, max friction ratio, ZMP margin, impact energy loss, step length, speed) and the
/// PNGs overlay joint angles, torques, ground forces and ZMP. Drawn by
/// scripts/plots/compare_gaits.py.
#include <string>

#include <CLI/CLI.hpp>

namespace gaitopt::apps {

struct CompareOptions {
  std::string a_dir, b_dir, out_dir;
};

void runCompare(const CompareOptions& options);
void registerCompareCommand(CLI::App& app);

}  // namespace gaitopt::apps
