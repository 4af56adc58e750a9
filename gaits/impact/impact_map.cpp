#include "gaits/impact/impact_map.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

namespace gaitopt::gaits {
namespace {

void checkAxis(const GridAxis& a, MapAxis which, std::string_view name) {
  const bool angle = which != MapAxis::kStepLength;
  const double unit = angle ? kDeg : 1.0;
  const char* unit_name = angle ? "deg" : "m";
  if (a.count < 1) throw std::invalid_argument(fmt::format("{}: count {} < 1", name, a.count));
  if (!std::isfinite(a.first) || !std::isfinite(a.last))
    throw std::invalid_argument(fmt::format("{}: bounds must be finite numbers", name));
  // Equal ends with a count above 1 would map one point several times, counted as many.
  if ((a.count == 1) != (a.first == a.last) || a.first > a.last)
    throw std::invalid_argument(
        fmt::format("{}: range {:.6g}:{:.6g}:{} must have first < last, or first = last when "
                    "count is 1",
                    name, a.first / unit, a.last / unit, a.count));
  const double upper = angle ? std::numbers::pi : std::numeric_limits<double>::infinity();
  if (!(a.first > 0 && a.last < upper))
    throw std::invalid_argument(
        fmt::format("{}: {:.6g}..{:.6g} {} outside the open range (0, {:.6g}) {}", name,
                    a.first / unit, a.last / unit, unit_name, upper / unit, unit_name));
}

/// Grid index (step, sigma, alpha) of point i; alpha varies fastest.
std::array<int, 3> gridIndex(const ImpactGrid& grid, size_t i) {
  const size_t n1 = grid.axes[1].count, n2 = grid.axes[2].count;
  return {static_cast<int>(i / (n1 * n2)), static_cast<int>(i / n2 % n1), static_cast<int>(i % n2)};
}

}  // namespace

size_t ImpactGrid::size() const {
  return static_cast<size_t>(axes[0].count) * axes[1].count * axes[2].count;
}

size_t ImpactGrid::index(const std::array<int, 3>& k) const {
  return (static_cast<size_t>(k[0]) * axes[1].count + k[1]) * axes[2].count + k[2];
}

ImpactPostureParams ImpactGrid::params(const std::array<int, 3>& k) const {
  return {axes[0].value(k[0]), axes[1].value(k[1]), axes[2].value(k[2]), approach_speed};
}

void checkImpactGrid(const dynamics::Model& model, const ImpactGrid& grid,
                     const ImpactAxisNames& names) {
  for (MapAxis a : {MapAxis::kStepLength, MapAxis::kKneeBias, MapAxis::kApproachAngle})
    checkAxis(grid.axis(a), a, names[static_cast<size_t>(a)]);
  if (!(grid.approach_speed > 0 && std::isfinite(grid.approach_speed)))
    throw std::invalid_argument(
        fmt::format("approach_speed: {} m/s must be positive", grid.approach_speed));
  // The hip reach shrinks as the knee bends, so the longest step at the largest sigma binds.
  const double sigma = grid.axis(MapAxis::kKneeBias).last;
  const double longest = grid.axis(MapAxis::kStepLength).last;
  if (!(longest < maxImpactStepLength(model, sigma)))
    throw std::invalid_argument(fmt::format(
        "{}: {:.6g} m is longer than the legs reach at knee bias {:.6g} deg (< {:.4f} m)", names[0],
        longest, sigma / kDeg, maxImpactStepLength(model, sigma)));
}

ImpactMap sweepImpactMap(const dynamics::Model& model, const ImpactGrid& grid, int jobs,
                         const parallel::ProgressFn& progress) {
  checkImpactGrid(model, grid);
  ImpactMap map{grid, std::vector<ImpactPoint>(grid.size())};
  constexpr std::size_t kChunk = 64;  // a point takes microseconds
  parallel::parallelFor(
      map.points.size(), jobs,
      [&](std::size_t i) {
        map.points[i] = evaluateImpactPoint(model, grid.params(gridIndex(grid, i)));
      },
      progress, kChunk);
  return map;
}

std::vector<TypeChange> typeChangesAlong(const ImpactMap& map, MapAxis axis,
                                         std::array<int, 3> through) {
  const auto a = static_cast<size_t>(axis);
  const GridAxis& g = map.grid.axes[a];
  std::vector<TypeChange> changes;
  for (int k = 0; k + 1 < g.count; ++k) {
    std::array<int, 3> before = through, after = through;
    before[a] = k;
    after[a] = k + 1;
    const dynamics::ImpactType from = map.at(before).type, to = map.at(after).type;
    if (from != to) changes.push_back({before, from, to, 0.5 * (g.value(k) + g.value(k + 1))});
  }
  return changes;
}

std::vector<TypeChange> typeChanges(const ImpactMap& map, MapAxis axis) {
  const auto a = static_cast<size_t>(axis);
  const auto& axes = map.grid.axes;
  std::vector<TypeChange> all;
  for (int i = 0; i < axes[(a + 1) % 3].count; ++i)
    for (int j = 0; j < axes[(a + 2) % 3].count; ++j) {
      std::array<int, 3> through{};
      through[(a + 1) % 3] = i;
      through[(a + 2) % 3] = j;
      const auto line = typeChangesAlong(map, axis, through);
      all.insert(all.end(), line.begin(), line.end());
    }
  return all;
}

}  // namespace gaitopt::gaits
