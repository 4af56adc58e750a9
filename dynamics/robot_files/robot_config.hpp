#pragma once
/// @file robot_config.hpp
/// Reads a robot YAML (configs/robots/*.yaml) into an immutable Model, validating every value.
#include <string>

#include "dynamics/model.hpp"

namespace gaitopt::dynamics {

/// Loads and validates a robot file.
/// @throws config::ConfigError naming the file, the key (and line) and what was expected, for a
///         missing, unknown, non-numeric or out-of-range value, or an impossible chain.
Model loadRobot(const std::string& path);

}  // namespace gaitopt::dynamics
