#pragma once
/// @file optimize_command.hpp
/// `gaitopt optimize --config FILE --out DIR [--warm-start DIR] [--rate HZ] [--quiet]
/// [--no-plots]`: solves the gait OCP of the config from its polynomial initial guess (or from a
/// previous result) and writes trajectory.csv, summary.json and pictures.
#include <string>

#include <CLI/CLI.hpp>

#include "apps/output_options.hpp"

namespace gaitopt::apps {

struct OptimizeOptions {
  std::string config_path;
  OutputOptions output;
  std::string warm_start;  ///< result folder whose trajectory.csv seeds the solve ("" = none)
  std::vector<std::string> sets;  ///< --set KEY=VALUE, config values replaced
  bool quiet = false;
};

void runOptimize(const OptimizeOptions& options);
void registerOptimizeCommand(CLI::App& app);

}  // namespace gaitopt::apps
