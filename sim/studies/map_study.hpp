#pragma once
/// @file map_study.hpp
/// A 2-D stability map (`gaitopt stability --map`): two scenario parameters varied on a grid,
/// one walk per point (rows of sweep_file.hpp keyed by both values), and the walking region: how
/// many points walk all their steps, the walking interval of the second parameter on every value
/// of the first, and the largest all-walking rectangles of the grid (anywhere, and around the
/// nominal point).
#include <map>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "sim/studies/sweep_study.hpp"

namespace gaitopt::sim {

/// One axis of a map: the parameter, its grid values and its nominal value.
struct MapParameter {
  const SweepParameter* parameter = nullptr;
  std::vector<double> values;  ///< increasing
  double nominal = 0;
};

/// Walks `scenario` with `a` at value_a and `b` at value_b (model: the reference's robot).
SweepRow walkMapPoint(const dynamics::Model& model, const Reference& reference, Scenario scenario,
                      const std::string& a, double value_a, const std::string& b, double value_b);

/// An all-walking rectangle of grid points, by index, both ends included.
struct GridRectangle {
  int a_first = 0, a_last = -1, b_first = 0, b_last = -1;
  int points() const { return (a_last - a_first + 1) * (b_last - b_first + 1); }
};

/// The largest rectangle (most points; ties: the first found, a then b ascending) whose points
/// all walk, among those containing (a_index, b_index), or anywhere when an index is < 0.
/// `walks` is indexed [a][b]. An empty rectangle (points() == 0) when none.
GridRectangle largestWalkingRectangle(const std::vector<std::vector<bool>>& walks, int a_index = -1,
                                      int b_index = -1);

/// The region of the grid a x b where every point walks all its steps (rows keyed as
/// SweepFile::key(a, b); a missing row counts as not walking): parameters (name, unit,
/// meaning, geometric, values, from, to, nominal), points, points_walked, nominal_walks (the grid
/// point nearest the nominal one), per_row (for every value of a, walkingInterval of b around b's
/// nominal value), largest_rectangle and largest_rectangle_around_nominal ({a_from, a_to, b_from,
/// b_to, points} or null).
nlohmann::ordered_json walkingRegion(const MapParameter& a, const MapParameter& b,
                                     const std::map<std::string, SweepRow>& rows);

}  // namespace gaitopt::sim
