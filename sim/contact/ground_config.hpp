#pragma once
/// @file ground_config.hpp
/// Reads a ground file (configs/grounds/*.yaml) into a GroundModel with the project's strict
/// reader: `model` is rigid, impedance, lcp or dart, each with its own keys; unknown or missing
/// keys and out-of-range values are ConfigErrors naming the file, key and line.
#include <string>

#include "sim/contact/ground_model.hpp"

namespace gaitopt::sim {

/// @throws config::ConfigError on a missing file, bad YAML, an unknown or missing key, or a
///         value out of range.
GroundModel loadGround(const std::string& yaml_path);

}  // namespace gaitopt::sim
