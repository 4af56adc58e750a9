#include "library/grid.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>

#include <fmt/format.h>

namespace gaitopt::library {

Grid::Grid(std::array<std::vector<double>, 3> axes) : axes_(std::move(axes)) {
  for (const auto& axis : axes_)
    if (axis.empty()) throw std::invalid_argument("grid: an axis without values");
  std::array<int, 3> at{};
  for (at[0] = 0; at[0] < static_cast<int>(axes_[0].size()); ++at[0])
    for (at[1] = 0; at[1] < static_cast<int>(axes_[1].size()); ++at[1])
      for (at[2] = 0; at[2] < static_cast<int>(axes_[2].size()); ++at[2]) {
        GridPoint p;
        p.index = size();
        p.at = at;
        for (int a = 0; a < 3; ++a) p.values[a] = axes_[a][static_cast<std::size_t>(at[a])];
        p.name = fmt::format("v{:.3f}_L{:.3f}_s{:+.3f}", p.values[0], p.values[1], p.values[2]);
        points_.push_back(p);
      }
  // The name is the point's folder and index key: two points must not share it.
  std::set<std::string> names;
  for (const auto& p : points_)
    if (!names.insert(p.name).second)
      throw std::invalid_argument(fmt::format(
          "grid: two points are both named {}: axis values must differ in their third decimal",
          p.name));
}

int Grid::indexOf(const std::array<int, 3>& at) const {
  return (at[0] * static_cast<int>(axes_[1].size()) + at[1]) * static_cast<int>(axes_[2].size()) +
         at[2];
}

std::vector<int> Grid::neighbours(int index) const {
  std::vector<int> out;
  for (int a = 0; a < 3; ++a)
    for (int step : {-1, 1}) {
      std::array<int, 3> at = point(index).at;
      at[a] += step;
      if (at[a] >= 0 && at[a] < static_cast<int>(axes_[a].size())) out.push_back(indexOf(at));
    }
  return out;
}

double Grid::distance(int a, int b) const {
  double d2 = 0;
  for (int k = 0; k < 3; ++k) {
    const double d = point(a).at[k] - point(b).at[k];
    d2 += d * d;
  }
  return std::sqrt(d2);
}

int Grid::nearest(const std::array<double, 3>& values) const {
  std::array<int, 3> at{};
  for (int a = 0; a < 3; ++a) {
    const auto& axis = axes_[a];
    const auto it = std::min_element(axis.begin(), axis.end(), [&](double x, double y) {
      return std::abs(x - values[a]) < std::abs(y - values[a]);
    });
    at[a] = static_cast<int>(it - axis.begin());
  }
  return indexOf(at);
}

}  // namespace gaitopt::library
