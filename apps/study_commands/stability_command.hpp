#pragma once
/// @file stability_command.hpp
/// `gaitopt stability --reference DIR [scenario options] --sweep NAME[=a:b:n] ...
/// --map A[=a:b:n],B[=c:d:m] ... --out DIR [--jobs N] [--poincare]`: where walking stops. Each
/// sweep varies one parameter of the scenario (push, mass_error, length_error, friction,
/// stiffness, gain_scale) around its nominal value and walks every point; each map varies two on
/// a grid (sim/studies/map_study.hpp); a point fails on a fall or slip. Points run in parallel (all
/// cores by default), each row is on disk as soon as it is done, and a rerun skips the finished
/// points. Writes sweep_<NAME>.csv, map_<A>_<B>.csv, summary.json (the walking interval around the
/// nominal value per sweep, the walking region per map), stability.png and map_<A>_<B>.png.
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "apps/study_commands/scenario_options.hpp"

namespace gaitopt::apps {

struct StabilityOptions {
  sim::ScenarioSettings scenario;
  std::vector<std::string> sweeps;  ///< NAME or NAME=a:b:n
  std::vector<std::string> maps;    ///< A[=a:b:n],B[=c:d:m]
  std::string out_dir;
  int jobs = 0;
  bool poincare = false;
  bool quiet = false;
  bool plots = true;
};

void runStability(const StabilityOptions& options);
void registerStabilityCommand(CLI::App& app);

}  // namespace gaitopt::apps
