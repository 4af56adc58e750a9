#pragma once
/// @file scenario_options.hpp
/// The command-line options shared by `gaitopt simulate` and `gaitopt stability`: which gait,
/// controller, ground and plant to walk.
#include <CLI/CLI.hpp>
#include "sim/scenario/reference_folder.hpp"
#include "sim/scenario/scenario.hpp"
#include "sim/scenario/scenario_settings.hpp"

namespace gaitopt::apps {

/// Adds --reference, --robot, --controller, --ground, --steps, --uncertainty-case, --friction,
/// --push, --gain-scale, --uncertainty-on and --set.
void addScenarioOptions(CLI::App* cmd, sim::ScenarioSettings& o);

/// The gait a controller needs (HZD's: no DSP, every joint but the ankle actuated, a growing
/// phase variable) is an input requirement, checked before anything is walked or written.
/// @throws io::CommandError (exit 2) naming the option and the folder.
void checkControllerFitsReference(const sim::ReferenceFolder& ref, const sim::Reference& reference,
                                  const sim::Scenario& scenario);

}  // namespace gaitopt::apps
