#pragma once
/// @file scenario_options.hpp
/// The command-line options shared by `gaitopt simulate` and `gaitopt stability`: which gait,
/// controller, ground and plant to walk.
#include <CLI/CLI.hpp>
#include "sim/scenario/scenario_settings.hpp"

namespace gaitopt::apps {

/// Adds --reference, --robot, --controller, --ground, --steps, --uncertainty-case, --friction,
/// --push, --gain-scale, --uncertainty-on and --set.
void addScenarioOptions(CLI::App* cmd, sim::ScenarioSettings& o);

}  // namespace gaitopt::apps
