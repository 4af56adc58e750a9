#pragma once
/// @file compare_command.hpp
/// `gaitopt compare A B [C [D]] --out DIR`: two to four gait result folders side by side.
/// DIR/comparison.md holds the table (what each gait is: polynomial with Mu's hip plan or with
/// the hip searched for the foot, or optimal; energy, cost of transport, torque-squared integral,
/// peak torque per joint, min normal force, max friction ratio, ZMP margin, impact energy loss,
/// step length, speed; each against A) and the PNGs overlay joint angles, torques, ground forces
/// and ZMP. Drawn by plots/compare_gaits.py.
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace gaitopt::apps {

struct CompareOptions {
  std::vector<std::string> dirs;  ///< the gait folders, A first
  std::string out_dir;
};

void runCompare(const CompareOptions& options);
void registerCompareCommand(CLI::App& app);

}  // namespace gaitopt::apps
