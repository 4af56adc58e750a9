#pragma once
/// @file poly_command.hpp
/// `gaitopt poly --robot FILE --gait FILE --out DIR [--rate HZ] [--no-plots]`: designs the
/// polynomial gait of Mu (2004) ch. 3 and writes trajectory.csv, summary.json and pictures.
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "apps/output_options.hpp"

namespace gaitopt::apps {

struct PolyOptions {
  std::string robot_path;
  std::string gait_path;
  OutputOptions output;
  std::vector<std::string> sets;  ///< --set KEY=VALUE on the gait config
};

void runPoly(const PolyOptions& options);
void registerPolyCommand(CLI::App& app);

}  // namespace gaitopt::apps
