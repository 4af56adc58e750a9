#include "library/grid.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>

#include <fmt/format.h>

namespace gaitopt::library {
namespace {

std::string pointName(const std::vector<double>& v, const std::vector<std::string>& names) {
  std::string name = fmt::format("v{:.3f}_L{:.3f}_s{:+.3f}", v[kSpeed], v[kStepLength], v[kSlope]);
  for (std::size_t a = kWalkAxes; a < v.size(); ++a)
    name += fmt::format("_{}={:.6g}", names[a], v[a]);
  return name;
}

}  // namespace

Grid::Grid(const std::array<std::vector<double>, kWalkAxes>& walk, std::vector<GridAxis> config)
    : axes_(walk.begin(), walk.end()),
      names_(kAxisNames.begin(), kAxisNames.end()),
      config_(std::move(config)) {
  for (const auto& axis : config_) {
    axes_.push_back(axis.values);
    names_.push_back(axis.key);
  }
  for (std::size_t a = 0; a < axes_.size(); ++a)
    if (axes_[a].empty())
      throw std::invalid_argument(fmt::format("grid: the axis {} has no values", names_[a]));
  // Counting in mixed radix, the last axis fastest.
  std::vector<int> at(axes_.size(), 0);
  for (bool done = false; !done;) {
    addPoint(at);
    done = true;
    for (std::size_t a = axes_.size(); a-- > 0;) {
      if (++at[a] < static_cast<int>(axes_[a].size())) {
        done = false;
        break;
      }
      at[a] = 0;
    }
  }
  // The name is the point's folder and index key: two points must not share it.
  std::set<std::string> names;
  for (const auto& p : points_)
    if (!names.insert(p.name).second)
      throw std::invalid_argument(fmt::format(
          "grid: two points are both named {}: speed, step length and slope must differ in "
          "their third decimal, config keys in their sixth digit",
          p.name));
}

void Grid::addPoint(const std::vector<int>& at) {
  GridPoint p;
  p.index = size();
  p.at = at;
  for (std::size_t a = 0; a < axes_.size(); ++a)
    p.values.push_back(axes_[a][static_cast<std::size_t>(at[a])]);
  p.name = pointName(p.values, names_);
  points_.push_back(std::move(p));
}

int Grid::indexOf(const std::vector<int>& at) const {
  int index = 0;
  for (std::size_t a = 0; a < axes_.size(); ++a)
    index = index * static_cast<int>(axes_[a].size()) + at[a];
  return index;
}

std::vector<int> Grid::neighbours(int index) const {
  std::vector<int> out;
  for (std::size_t a = 0; a < axes_.size(); ++a)
    for (int step : {-1, 1}) {
      std::vector<int> at = point(index).at;
      at[a] += step;
      if (at[a] >= 0 && at[a] < static_cast<int>(axes_[a].size())) out.push_back(indexOf(at));
    }
  return out;
}

double Grid::distance(int a, int b) const {
  double d2 = 0;
  for (std::size_t k = 0; k < axes_.size(); ++k) {
    const double d = point(a).at[k] - point(b).at[k];
    d2 += d * d;
  }
  return std::sqrt(d2);
}

int Grid::nearest(const std::vector<double>& values) const {
  if (values.size() != axes_.size())
    throw std::invalid_argument(
        fmt::format("grid: {} values for {} axes", values.size(), axes_.size()));
  std::vector<int> at(axes_.size(), 0);
  for (std::size_t a = 0; a < axes_.size(); ++a) {
    const auto& axis = axes_[a];
    const auto it = std::min_element(axis.begin(), axis.end(), [&](double x, double y) {
      return std::abs(x - values[a]) < std::abs(y - values[a]);
    });
    at[a] = static_cast<int>(it - axis.begin());
  }
  return indexOf(at);
}

}  // namespace gaitopt::library
