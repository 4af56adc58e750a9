#pragma once
/// @file library_config.hpp
/// configs/library/*.yaml: a gait library is one OCP config (the base problem) solved over a
/// grid of walking speed x step length x ground slope. Each axis is one number, a list, or a
/// range {from, to, count}; an axis left out keeps the base problem's value.
#include <array>
#include <string>
#include <vector>

#include "ocp/problem/ocp_config.hpp"

namespace gaitopt::library {

/// The grid's axes, in this order everywhere (folder names, index columns, interpolation).
enum Axis : int { kSpeed = 0, kStepLength = 1, kSlope = 2 };
inline constexpr std::array<const char*, 3> kAxisNames = {"speed", "step_length", "slope"};
inline constexpr std::array<const char*, 3> kAxisUnits = {"m/s", "m", "rad"};

struct LibraryConfig {
  std::string name;
  std::string path;      ///< of the YAML file
  std::string ocp_path;  ///< the base problem
  ocp::OcpConfig base;
  std::array<std::vector<double>, 3> axes;  ///< sorted, distinct values per Axis
};

/// The base problem's own point: speed = step_length / (SSP + DSP duration).
std::array<double, 3> basePoint(const ocp::OcpConfig& base);

/// The library of the config file `path`, with `overrides` (`--set KEY=VALUE`) in place of its
/// values. @throws config::ConfigError naming file, key and expectation.
LibraryConfig loadLibraryConfig(const std::string& path,
                                const std::vector<config::Override>& overrides = {});

}  // namespace gaitopt::library
