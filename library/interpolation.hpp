#pragma once
/// @file interpolation.hpp
/// A gait between the points of a library, as a controller would take it online: multilinear
/// interpolation between the solved gaits at the corners of the grid cell holding the query, in
/// phase-normalised time s = t / T_phase. Angles, their s-derivatives (dtheta T, ddtheta T^2)
/// and the swing-tip force are blended with the corners' weights, the rates are turned back to
/// time with the query's own durations (T = step_length / speed, the corners' SSP/DSP split),
/// the blend is put back on its contacts (contact_projection.hpp), and the torques and stance
/// force follow from that motion by inverse dynamics. The blend is not a solution of the
/// problem; interpolation_test.cpp measures how far off it is.
#include <array>
#include <functional>

#include "dynamics/model.hpp"
#include "gaits/trajectory/trajectory.hpp"
#include "library/grid.hpp"

namespace gaitopt::library {

/// The solved gait of a grid point, or nullptr when it has none.
using GaitLookup = std::function<const gaits::Trajectory*(int point)>;

/// The corners of the cell holding `values` (one per axis of the grid) and their weights
/// (summing to 1; corners of weight 0 left out). @throws std::domain_error when a value lies
/// outside its axis, std::invalid_argument for a count of values other than the axes'.
std::vector<std::pair<int, double>> cellWeights(const Grid& grid,
                                                const std::vector<double>& values);

/// The interpolated step on the grid j / rate_hz, with both ends of each phase.
/// @throws std::domain_error outside the grid or when a corner has no solved gait,
///         std::invalid_argument when the corners' phases differ.
gaits::Trajectory interpolateGait(const Grid& grid, const GaitLookup& gait_at,
                                  const dynamics::Model& model, const std::vector<double>& values,
                                  double rate_hz);

}  // namespace gaitopt::library
