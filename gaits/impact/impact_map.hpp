#pragma once
/// @file impact_map.hpp
/// The impact-type map of Mu (2004) sec. 5.3 (Figs. 5.2-5.7): impact points on a grid over step
/// length, stance knee bias sigma and swing-tip approach angle alpha, evaluated in parallel, and
/// the places along each axis where the impact type changes.
#include <array>
#include <cstddef>
#include <string_view>
#include <vector>

#include "gaits/impact/impact_point.hpp"
#include "parallel/parallel_for.hpp"

namespace gaitopt::gaits {

/// `count` evenly spaced values from `first` to `last` inclusive (count == 1: first only).
struct GridAxis {
  double first = 0;
  double last = 0;
  int count = 1;
  double value(int k) const {
    return count == 1 ? first : first + (last - first) * k / (count - 1);
  }
};

enum class MapAxis { kStepLength = 0, kKneeBias = 1, kApproachAngle = 2 };

/// A grid of pre-impact states; the approach angle varies fastest, the step length slowest.
struct ImpactGrid {
  std::array<GridAxis, 3> axes;  ///< indexed by MapAxis: step_length [m], sigma, alpha [rad]
  double approach_speed = 1;     ///< V_e [m/s]; types and ratios do not depend on it (sec. 5.2)

  const GridAxis& axis(MapAxis a) const { return axes[static_cast<size_t>(a)]; }
  size_t size() const;
  size_t index(const std::array<int, 3>& k) const;
  ImpactPostureParams params(const std::array<int, 3>& k) const;
};

/// What checkImpactGrid's messages call the axes (step length, knee bias, approach angle): the
/// grid's own names, or the options a command line parsed them from.
using ImpactAxisNames = std::array<std::string_view, 3>;
inline constexpr ImpactAxisNames kImpactAxisNames = {"step_length", "knee_bias", "approach_angle"};

/// @throws std::invalid_argument naming the axis (by `names`) when a count is < 1, a bound is
///         not finite, first > last, count == 1 with first != last, an angle leaves (0, pi), a
///         step length is not positive, or the longest step cannot be reached at the largest
///         knee bias.
void checkImpactGrid(const dynamics::Model& model, const ImpactGrid& grid,
                     const ImpactAxisNames& names = kImpactAxisNames);

struct ImpactMap {
  ImpactGrid grid;
  std::vector<ImpactPoint> points;  ///< grid.size() points in grid.index order

  const ImpactPoint& at(const std::array<int, 3>& k) const { return points[grid.index(k)]; }
};

/// Evaluates every grid point with `jobs` std::thread workers (>= 1). The result does not depend
/// on `jobs`: each point is a pure function of its parameters and has its own slot.
/// @throws std::invalid_argument as checkImpactGrid, or when jobs < 1.
ImpactMap sweepImpactMap(const dynamics::Model& model, const ImpactGrid& grid, int jobs,
                         const parallel::ProgressFn& progress = {});

/// A change of impact type between neighbouring grid points along one axis.
struct TypeChange {
  std::array<int, 3> before;  ///< grid index of the point before the change
  dynamics::ImpactType from{}, to{};
  double at = 0;  ///< midpoint of the two axis values (the boundary to half a grid step)
};

/// The type changes along `axis` on the grid line through `through` (its entry for `axis` is
/// ignored), in increasing order of the axis value.
std::vector<TypeChange> typeChangesAlong(const ImpactMap& map, MapAxis axis,
                                         std::array<int, 3> through);

/// typeChangesAlong over every grid line parallel to `axis`.
std::vector<TypeChange> typeChanges(const ImpactMap& map, MapAxis axis);

}  // namespace gaitopt::gaits
