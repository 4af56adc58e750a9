#pragma once
/// @file grid.hpp
/// The points of a gait library: the Cartesian product of its axes, numbered with the first
/// axis (speed) varying slowest and the last fastest. The walk's own three axes (speed, step
/// length, slope) come first, then any config keys the library sweeps. Neighbours differ by one
/// step along one axis.
#include <array>
#include <string>
#include <vector>

namespace gaitopt::library {

/// The walk's own axes, first on every grid and in this order (folder names, index columns,
/// interpolation): they set the step itself (point_problem.hpp).
enum Axis : int { kSpeed = 0, kStepLength = 1, kSlope = 2 };
inline constexpr int kWalkAxes = 3;
inline constexpr std::array<const char*, kWalkAxes> kAxisNames = {"speed", "step_length", "slope"};
inline constexpr std::array<const char*, kWalkAxes> kAxisUnits = {"m/s", "m", "rad"};

/// An axis over a numeric value of the base OCP config, named by its key path as `--set`
/// names it ("constraints.friction_margin").
struct GridAxis {
  std::string key;
  std::vector<double> values;  ///< sorted, distinct
};

struct GridPoint {
  int index = 0;
  std::vector<int> at;         ///< position along each axis
  std::vector<double> values;  ///< speed [m/s], step length [m], slope [rad], config keys
  std::string name;  ///< folder name, e.g. "v0.600_L0.350_s+0.000" (+ "_KEY=VALUE" per key)
  /// Speed, step length and slope.
  std::array<double, kWalkAxes> walk() const { return {values[0], values[1], values[2]}; }
};

class Grid {
 public:
  /// @throws std::invalid_argument for an axis without values or two points of one name.
  explicit Grid(const std::array<std::vector<double>, kWalkAxes>& walk,
                std::vector<GridAxis> config = {});

  int size() const { return static_cast<int>(points_.size()); }
  const GridPoint& point(int index) const { return points_.at(static_cast<std::size_t>(index)); }
  /// Every axis' values: the walk's three, then the config keys'.
  const std::vector<std::vector<double>>& axes() const { return axes_; }
  /// The name of axis `a`: kAxisNames, then the config keys.
  const std::string& axisName(int a) const { return names_.at(static_cast<std::size_t>(a)); }
  const std::vector<GridAxis>& configAxes() const { return config_; }
  int dimensions() const { return static_cast<int>(axes_.size()); }
  /// Points one step away along one axis.
  std::vector<int> neighbours(int index) const;
  /// Distance in grid steps (Euclidean over the axes' positions): which solved point is the
  /// nearest warm start.
  double distance(int a, int b) const;
  /// The point nearest to `values` (one per axis), axis by axis.
  int nearest(const std::vector<double>& values) const;

 private:
  int indexOf(const std::vector<int>& at) const;
  void addPoint(const std::vector<int>& at);

  std::vector<std::vector<double>> axes_;
  std::vector<std::string> names_;
  std::vector<GridAxis> config_;
  std::vector<GridPoint> points_;
};

}  // namespace gaitopt::library
