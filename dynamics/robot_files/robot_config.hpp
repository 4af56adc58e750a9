#pragma once
/// @file robot_config.hpp
/// Reads a robot YAML (configs/robots/*.yaml) into an immutable Model, validating every value.
#include <string>
#include <vector>

#include "config/overrides.hpp"

#include "dynamics/model.hpp"

namespace gaitopt::dynamics {

/// Loads and validates a robot file.
/// @throws config::ConfigError naming the file, the key (and line) and what was expected, for a
///         missing, unknown, non-numeric or out-of-range value, or an impossible chain.
/// `overrides` replace values of the file before it is checked (a command's --set robot.KEY=V).
Model loadRobot(const std::string& path, const std::vector<config::Override>& overrides = {});

}  // namespace gaitopt::dynamics
