#pragma once
/// @file simulate_command.hpp
/// `gaitopt simulate --reference DIR [--controller NAME] [--ground NAME|FILE] [--steps N]
/// [--uncertainty-case 1|2|3] [--friction MU] [--push P] --out DIR`: walks an exported gait in
/// closed loop and writes walk.csv, steps.csv, stick.csv, summary.json (steps_completed, fell,
/// max_tracking_error, poincare_max_multiplier) and pictures.
#include <CLI/CLI.hpp>

#include "apps/output_options.hpp"
#include "apps/study_commands/scenario_options.hpp"

namespace gaitopt::apps {

struct SimulateOptions {
  sim::ScenarioSettings scenario;
  OutputOptions output;
  bool poincare = true;  ///< the Poincare map of the cycle (rigid ground)
  bool quiet = false;
};

void runSimulate(const SimulateOptions& options);
void registerSimulateCommand(CLI::App& app);

}  // namespace gaitopt::apps
