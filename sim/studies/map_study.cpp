#include "sim/studies/map_study.hpp"

#include <cmath>
#include <cstddef>

namespace gaitopt::sim {
namespace {

bool walksAll(const SweepRow& r) {
  return !r.fell && r.steps_completed == r.steps_requested;
}

/// The index of the value nearest `x`.
int nearest(const std::vector<double>& values, double x) {
  int best = 0;
  for (std::size_t i = 1; i < values.size(); ++i)
    if (std::abs(values[i] - x) < std::abs(values[static_cast<std::size_t>(best)] - x))
      best = static_cast<int>(i);
  return best;
}

nlohmann::ordered_json axisJson(const MapParameter& axis) {
  return {{"name", axis.parameter->name()},
          {"unit", axis.parameter->unit()},
          {"meaning", axis.parameter->meaning},
          // Spaced by a constant ratio (stiffness): the picture draws it on a log axis.
          {"geometric", axis.parameter->geometric},
          {"values", axis.values.size()},
          {"from", keyedValue(axis.values.front())},
          {"to", keyedValue(axis.values.back())},
          {"nominal", axis.nominal}};
}

nlohmann::ordered_json rectangleJson(const GridRectangle& r, const MapParameter& a,
                                     const MapParameter& b) {
  if (r.points() == 0) return nullptr;
  const auto at = [](const MapParameter& axis, int i) {
    return keyedValue(axis.values[static_cast<std::size_t>(i)]);
  };
  return {{"a_from", at(a, r.a_first)},
          {"a_to", at(a, r.a_last)},
          {"b_from", at(b, r.b_first)},
          {"b_to", at(b, r.b_last)},
          {"points", r.points()}};
}

}  // namespace

SweepRow walkMapPoint(const dynamics::Model& model, const Reference& reference, Scenario scenario,
                      const std::string& a, double value_a, const std::string& b, double value_b) {
  setSweepValue(scenario, a, value_a);
  SweepRow row = walkSweepPoint(model, reference, std::move(scenario), b, value_b);
  row.value = value_a;
  row.value_b = value_b;
  return row;
}

GridRectangle largestWalkingRectangle(const std::vector<std::vector<bool>>& walks, int a_index,
                                      int b_index) {
  // 2-D prefix sums of walking points; every rectangle is then checked in O(1). A map holds at
  // most a few thousand points, so the O(n^2 m^2) enumeration is instantaneous.
  const int n = static_cast<int>(walks.size()), m = n ? static_cast<int>(walks[0].size()) : 0;
  std::vector<std::vector<int>> sum(n + 1, std::vector<int>(m + 1, 0));
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < m; ++j)
      sum[i + 1][j + 1] = sum[i][j + 1] + sum[i + 1][j] - sum[i][j] +
                          (walks[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)] ? 1 : 0);
  const bool around = a_index >= 0 && b_index >= 0;
  GridRectangle best;
  for (int i0 = 0; i0 < n; ++i0)
    for (int i1 = i0; i1 < n; ++i1)
      for (int j0 = 0; j0 < m; ++j0)
        for (int j1 = j0; j1 < m; ++j1) {
          if (around && (a_index < i0 || a_index > i1 || b_index < j0 || b_index > j1)) continue;
          const GridRectangle r{i0, i1, j0, j1};
          const int walking = sum[i1 + 1][j1 + 1] - sum[i0][j1 + 1] - sum[i1 + 1][j0] + sum[i0][j0];
          if (walking == r.points() && r.points() > best.points()) best = r;
        }
  return best;
}

nlohmann::ordered_json walkingRegion(const MapParameter& a, const MapParameter& b,
                                     const std::map<std::string, SweepRow>& rows) {
  std::vector<std::vector<bool>> walks;
  auto per_row = nlohmann::ordered_json::array();
  int walked = 0;
  for (double va : a.values) {
    std::map<std::string, SweepRow> line;  // this value of a, keyed as a sweep of b
    walks.emplace_back();
    for (double vb : b.values) {
      const auto it = rows.find(SweepFile::key(va, vb));
      const bool w = it != rows.end() && walksAll(it->second);
      walks.back().push_back(w);
      walked += w ? 1 : 0;
      if (it != rows.end())
        line[SweepFile::key(vb)] = {keyedValue(vb), it->second.steps_completed,
                                    it->second.steps_requested, it->second.fell,
                                    it->second.failure};
    }
    const nlohmann::ordered_json interval = walkingInterval(*b.parameter, line, b.nominal);
    per_row.push_back({{a.parameter->name(), keyedValue(va)},
                       {"walks_from", interval["walks_from"]},
                       {"walks_to", interval["walks_to"]}});
  }
  const int ia = nearest(a.values, a.nominal), ib = nearest(b.values, b.nominal);
  return {
      {"a", axisJson(a)},
      {"b", axisJson(b)},
      {"points", a.values.size() * b.values.size()},
      {"points_walked", walked},
      {"nominal_walks", bool(walks[static_cast<std::size_t>(ia)][static_cast<std::size_t>(ib)])},
      {"largest_rectangle", rectangleJson(largestWalkingRectangle(walks), a, b)},
      {"largest_rectangle_around_nominal",
       rectangleJson(largestWalkingRectangle(walks, ia, ib), a, b)},
      {"per_row", per_row}};
}

}  // namespace gaitopt::sim
