#pragma once
/// @file interpolate_command.hpp
/// `gaitopt interpolate --library DIR --speed V --step-length L [--slope S] --out DIR [--rate HZ]
/// [--no-plots]`: the gait at (V, L, S) blended from the solved gaits of a library
/// (library/interpolation.hpp), written as a result folder whose summary.json says how far it
/// misses the dynamics (max_dynamics_residual) and periodicity (periodicity_error).
#include <CLI/CLI.hpp>

namespace gaitopt::apps {

void registerInterpolateCommand(CLI::App& app);

}  // namespace gaitopt::apps
