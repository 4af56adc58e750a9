#pragma once
/// @file poly_command.hpp
/// `gaitopt poly --robot FILE --gait FILE --out DIR [--rate HZ] [--no-plots]`: designs the
/// polynomial gait of Mu (2004) ch. 3 and writes trajectory.csv, summary.json and pictures.
#include <string>

#include <CLI/CLI.hpp>

namespace gaitopt::apps {

struct PolyOptions {
  std::string robot_path;
  std::string gait_path;
  std::string out_dir;
  double rate_hz = 1000;
  bool plots = true;
};

void runPoly(const PolyOptions& options);
void registerPolyCommand(CLI::App& app);

}  // namespace gaitopt::apps
