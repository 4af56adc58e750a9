#pragma once
/// @file walk_memory.hpp
/// What a walk's log keeps in memory until the walk ends, refused up front when it would not
/// fit: a long walk otherwise died in bad_alloc after its whole computation.
#include <string>

#include "sim/scenario/scenario.hpp"

namespace gaitopt::sim {

/// @throws config::ConfigError keyed `steps_option` when `s.steps` steps of `step_time` [s],
/// logged at `rate_hz` (capped by the ground's time step; infinity: every step of the ground),
/// would keep more than a walk may take (4 GB).
void requireWalkFits(const Scenario& s, double step_time, double rate_hz,
                     const std::string& steps_option);

}  // namespace gaitopt::sim
