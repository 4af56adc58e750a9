#pragma once
/// @file library_config.hpp
/// configs/library/*.yaml: a gait library is one OCP config (the base problem) solved over a
/// grid of walking speed x step length x ground slope, and optionally over any numeric value of
/// the base problem's config (`constraints.friction_margin: [0.1, 0.2]`). Each axis is one
/// number, a list, or a range {from, to, count}; an axis left out keeps the base problem's value.
#include <array>
#include <string>
#include <vector>

#include "library/grid.hpp"
#include "ocp/problem/ocp_config.hpp"

namespace gaitopt::library {

struct LibraryConfig {
  std::string name;
  std::string path;      ///< of the YAML file
  std::string ocp_path;  ///< the base problem
  ocp::OcpConfig base;
  std::array<std::vector<double>, kWalkAxes> axes;  ///< sorted, distinct values per Axis
  /// The config keys swept, in the file's order, each value checked as the OCP file's would be.
  std::vector<GridAxis> config_axes;
  /// The base problem's value of each config axis: its file's, or the axis' middle value when
  /// the file leaves the key to its default. Where the library starts (library_run.hpp).
  std::vector<double> config_base;
};

/// The base problem's own point: speed = step_length / (SSP + DSP duration).
std::array<double, kWalkAxes> basePoint(const ocp::OcpConfig& base);

/// The base problem's point on every axis of the library's grid.
std::vector<double> basePoint(const LibraryConfig& config);

/// The base problem with the config axes' values of `point` set, as `--set KEY=VALUE` would.
/// @throws config::ConfigError as loadOcpConfig.
ocp::OcpConfig baseAt(const LibraryConfig& config, const GridPoint& point);

/// The library of the config file `path`, with `overrides` (`--set KEY=VALUE`) in place of its
/// values. @throws config::ConfigError naming file, key and expectation.
LibraryConfig loadLibraryConfig(const std::string& path,
                                const std::vector<config::Override>& overrides = {});

}  // namespace gaitopt::library
