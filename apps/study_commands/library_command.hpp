#pragma once
/// @file library_command.hpp
/// `gaitopt library --config FILE --out DIR [--jobs N] [--retry-failed] [--rate HZ] [--plots]
/// [--quiet]`: solves a gait library (library/library_config.hpp) point by point, each from the
/// nearest solved point, on every core, or across the ranks of `mpirun -np N gaitopt library
/// ...`; resumable. Writes DIR/points/<point>/, DIR/index.csv, DIR/index.json and a chart.
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace gaitopt::apps {

struct LibraryOptions {
  std::string config_path;
  std::string out_dir;
  int jobs = 0;  ///< worker threads (per MPI rank); 0: every core, or 1 per rank under MPI
  bool retry_failed = false;
  double rate_hz = 250;
  bool plots = false;  ///< pictures of every point (the library chart is always drawn)
  bool quiet = false;
  std::vector<std::string> sets;  ///< --set KEY=VALUE on the library config
};

void runLibrary(const LibraryOptions& options);
void registerLibraryCommand(CLI::App& app);

}  // namespace gaitopt::apps
