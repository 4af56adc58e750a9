#pragma once
/// @file ground_config.hpp
/// Reads a ground file (configs/grounds/*.yaml) into a GroundModel with the project's strict
/// reader: `model` is a ground registered in sim/walk/ground_registry.cpp, whose reader takes the
/// file's other keys; unknown or missing keys and out-of-range values are ConfigErrors naming the
/// file, key and line. The shipped grounds' readers are here, sharing the time-step range.
#include <string>
#include <vector>

#include "config/overrides.hpp"
#include "sim/contact/ground_model.hpp"

namespace gaitopt::config {
class YamlReader;
}

namespace gaitopt::sim {

/// @throws config::ConfigError on a missing file, bad YAML, an unknown ground or key, a missing
///         key, or a value out of range. `overrides` replace values of the file before it is
///         checked (a command's --set ground.KEY=V).
GroundModel loadGround(const std::string& yaml_path,
                       const std::vector<config::Override>& overrides = {});

/// `time_step` of a ground file: between 0.1 us and 10 ms, beyond which no ground of a walking
/// robot is resolved [s].
double groundTimeStep(const config::YamlReader& file);

/// The keys of each shipped ground's file besides `model`.
RigidGround readRigidGround(const config::YamlReader& file);
CompliantGround readImpedanceGround(const config::YamlReader& file);
LcpGround readLcpGround(const config::YamlReader& file);
DartGround readDartGround(const config::YamlReader& file);

}  // namespace gaitopt::sim
