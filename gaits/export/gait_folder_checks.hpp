#pragma once
/// @file gait_folder_checks.hpp
/// Whether a gait result folder (from `gaitopt poly` or `gaitopt optimize`) holds a gait to use
/// with a robot: the checks every reader of such a folder makes (a warm start, a closed-loop
/// walk, the Python reader, a library point) before it trusts its trajectory.csv.
#include <string>

#include "dynamics/model.hpp"

namespace gaitopt::gaits {

/// @throws config::ConfigError unless the result folder `dir` holds a usable gait of `model`:
/// no FAILED.txt, not "converged": false, and summary.json's robot (when recorded) is model's.
void requireGaitOf(const std::string& dir, const dynamics::Model& model);

/// requireGaitOf, and the robot the gait was designed on weighs what `model` does (summary.json's
/// total_mass, when recorded): a gait to walk or to read, where a warm start may come from
/// another robot of that name on purpose.
void requireDesignedFor(const std::string& dir, const dynamics::Model& model);

}  // namespace gaitopt::gaits
