#pragma once
/// @file impact_map_command.hpp
/// `gaitopt impact-map --robot FILE --out DIR [--step-lengths a:b:n] [--knee-bias a:b:n]
/// [--approach-angles a:b:n] [--approach-speed V] [--jobs N] [--quiet] [--no-plots]`: the
/// impact-type map of Mu (2004) sec. 5.3 over a grid of pre-impact states, written as
/// impact_map.csv, summary.json and impact_map.png.
#include <string>

#include <CLI/CLI.hpp>

namespace gaitopt::apps {

struct ImpactMapOptions {
  std::string robot_path;
  std::string out_dir;
  std::string step_lengths = "0.025:1.0:40";  ///< tip distance [m]: Mu's S_L 0.05..2.0 m
  std::string knee_bias = "1:60:60";          ///< sigma [deg]: Mu's 0..60 without 0
  std::string approach_angles = "5:175:35";   ///< alpha [deg]: Mu's 0..180 without the ends
  double approach_speed = 1.0;                ///< V_e [m/s]
  int jobs = 0;                               ///< worker threads; 0 = all cores
  bool quiet = false;
  bool plots = true;
};

void runImpactMap(const ImpactMapOptions& options);
void registerImpactMapCommand(CLI::App& app);

}  // namespace gaitopt::apps
