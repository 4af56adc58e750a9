#pragma once
/// @file grid.hpp
/// The points of a gait library: the Cartesian product of its axes, numbered with the speed
/// varying slowest, the slope fastest. Neighbours differ by one step along one axis.
#include <array>
#include <string>
#include <vector>

#include "library/library_config.hpp"

namespace gaitopt::library {

struct GridPoint {
  int index = 0;
  std::array<int, 3> at{};         ///< position along each Axis
  std::array<double, 3> values{};  ///< speed [m/s], step length [m], slope [rad]
  std::string name;                ///< folder name, e.g. "v0.600_L0.350_s+0.000"
};

class Grid {
 public:
  explicit Grid(std::array<std::vector<double>, 3> axes);

  int size() const { return static_cast<int>(points_.size()); }
  const GridPoint& point(int index) const { return points_.at(static_cast<std::size_t>(index)); }
  const std::array<std::vector<double>, 3>& axes() const { return axes_; }
  /// Points one step away along one axis.
  std::vector<int> neighbours(int index) const;
  /// Distance in grid steps (Euclidean over the axes' positions): which solved point is the
  /// nearest warm start.
  double distance(int a, int b) const;
  /// The point nearest to `values`, axis by axis.
  int nearest(const std::array<double, 3>& values) const;

 private:
  int indexOf(const std::array<int, 3>& at) const;

  std::array<std::vector<double>, 3> axes_;
  std::vector<GridPoint> points_;
};

}  // namespace gaitopt::library
