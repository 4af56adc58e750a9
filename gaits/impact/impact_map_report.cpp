#include "gaits/impact/impact_map_report.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <stdexcept>

#include <fmt/format.h>

#include "io/output/checked_write.hpp"

namespace gaitopt::gaits {
namespace {

using dynamics::ImpactType;

constexpr std::array<MapAxis, 3> kAxes = {MapAxis::kStepLength, MapAxis::kKneeBias,
                                          MapAxis::kApproachAngle};
constexpr std::array<ImpactType, 4> kTypes = {ImpactType::kSingle, ImpactType::kDouble,
                                              ImpactType::kEither, ImpactType::kNeither};

/// Axis name in the files and the factor from internal units to file units (m or deg).
std::pair<const char*, double> axisLabel(MapAxis axis) {
  switch (axis) {
    case MapAxis::kStepLength:
      return {"step_length", 1.0};
    case MapAxis::kKneeBias:
      return {"knee_bias_deg", 1 / kDeg};
    case MapAxis::kApproachAngle:
      return {"approach_angle_deg", 1 / kDeg};
  }
  return {"?", 1.0};
}

/// An axis value in file units, rounded to 12 significant digits (15 deg, not 14.999999999999998).
double fileValue(MapAxis axis, double value) {
  return std::stod(fmt::format("{:.12g}", value * axisLabel(axis).second));
}

std::string csvRow(const ImpactPoint& p) {
  const auto& d = p.double_model;
  const auto& s = p.single_model;
  return fmt::format(
      "{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{},{:.10g},{:.10g},{:.10g},{:.10g},"
      "{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:.10g},{:d},{:d},{}\n",
      p.params.step_length, 2 * p.params.step_length, p.params.knee_bias / kDeg,
      p.params.approach_angle / kDeg, p.params.approach_speed, p.hip_height,
      dynamics::toString(p.type), d.impulse_trailing(0), d.impulse_trailing(1),
      d.impulse_leading(0), d.impulse_leading(1), s.trailing_velocity(0), s.trailing_velocity(1),
      s.impulse_leading(0), s.impulse_leading(1), p.mu_l, p.mu_r, p.mu_s, d.friction_ok,
      s.friction_ok, dynamics::toString(p.lcp_type));
}

nlohmann::ordered_json gridJson(const ImpactGrid& grid) {
  nlohmann::ordered_json out;
  for (MapAxis a : kAxes) {
    const GridAxis& g = grid.axis(a);
    out[axisLabel(a).first] = {
        {"first", fileValue(a, g.first)}, {"last", fileValue(a, g.last)}, {"count", g.count}};
  }
  return out;
}

nlohmann::ordered_json countsJson(const ImpactMap& map, bool no_slip_only) {
  nlohmann::ordered_json out;
  for (ImpactType t : kTypes) {
    out[dynamics::toString(t)] = std::count_if(map.points.begin(), map.points.end(), [&](auto& p) {
      if (p.type != t) return false;
      if (!no_slip_only) return true;
      // A double impact must hold both tips (2.31b-c), a single one the colliding tip (2.37b).
      // Either model may follow in the 'either' region; no model is valid in 'neither'.
      const bool d = p.double_model.friction_ok, s = p.single_model.friction_ok;
      if (t == ImpactType::kNeither) return false;
      return t == ImpactType::kDouble ? d : t == ImpactType::kSingle ? s : d && s;
    });
  }
  return out;
}

/// For each of Mu's types, what the complementarity law allows at the same points.
nlohmann::ordered_json lcpCountsJson(const ImpactMap& map) {
  nlohmann::ordered_json out;
  for (ImpactType mu : kTypes) {
    nlohmann::ordered_json row;
    for (ImpactType lcp : kTypes)
      row[dynamics::toString(lcp)] =
          std::count_if(map.points.begin(), map.points.end(),
                        [&](const ImpactPoint& p) { return p.type == mu && p.lcp_type == lcp; });
    out[dynamics::toString(mu)] = row;
  }
  return out;
}

/// Per kind of type change along `axis`: how many grid lines show it and where (min, median,
/// max of the boundary in file units).
nlohmann::ordered_json boundaryStats(const ImpactMap& map, MapAxis axis) {
  std::map<std::pair<ImpactType, ImpactType>, std::vector<double>> where;
  for (const auto& c : typeChanges(map, axis)) where[{c.from, c.to}].push_back(c.at);
  auto out = nlohmann::ordered_json::array();
  for (auto& [kind, at] : where) {
    std::sort(at.begin(), at.end());
    out.push_back({{"from", dynamics::toString(kind.first)},
                   {"to", dynamics::toString(kind.second)},
                   {"lines", at.size()},
                   {"min", fileValue(axis, at.front())},
                   {"median", fileValue(axis, at[at.size() / 2])},
                   {"max", fileValue(axis, at.back())}});
  }
  return out;
}

int nearestIndex(const GridAxis& g, double value) {
  int best = 0;
  for (int k = 1; k < g.count; ++k)
    if (std::abs(g.value(k) - value) < std::abs(g.value(best) - value)) best = k;
  return best;
}

/// Mu's reference case, S_L 0.7 m (step_length 0.35 m), sigma 15, alpha 90 deg
/// (docs/derivations.md#impact-reference-values).
nlohmann::ordered_json referenceJson(const ImpactMap& map) {
  const std::array<double, 3> mu_case = {0.35, 15 * kDeg, 90 * kDeg};
  std::array<int, 3> k{};
  nlohmann::ordered_json through, lines;
  for (MapAxis a : kAxes) {
    const auto i = static_cast<size_t>(a);
    k[i] = nearestIndex(map.grid.axes[i], mu_case[i]);
    through[axisLabel(a).first] = fileValue(a, map.grid.axes[i].value(k[i]));
  }
  for (MapAxis a : kAxes) {
    auto changes = nlohmann::ordered_json::array();
    for (const auto& c : typeChangesAlong(map, a, k))
      changes.push_back({{"from", dynamics::toString(c.from)},
                         {"to", dynamics::toString(c.to)},
                         {"at", fileValue(a, c.at)}});
    lines[axisLabel(a).first] = changes;
  }
  return {{"through", through}, {"type", dynamics::toString(map.at(k).type)}, {"changes", lines}};
}

}  // namespace

void writeImpactMapCsv(const ImpactMap& map, const std::string& path) {
  std::string text =
      "step_length,mu_SL,knee_bias_deg,approach_angle_deg,approach_speed,hip_height,type,"
      "P_lx,P_ly,P_rx,P_ry,xdot_b,ydot_b,P_Sx,P_Sy,mu_L,mu_R,mu_S,double_no_slip,"
      "single_no_slip,lcp_type\n";
  for (const auto& p : map.points) text += csvRow(p);
  io::writeFileAtomically(path, text);
}

nlohmann::ordered_json impactMapSummary(const ImpactMap& map, const dynamics::Model& model) {
  nlohmann::ordered_json boundaries;
  for (MapAxis a : kAxes) boundaries[axisLabel(a).first] = boundaryStats(map, a);
  return {{"robot", model.name()},
          {"friction", model.friction()},
          {"approach_speed", map.grid.approach_speed},
          {"grid", gridJson(map.grid)},
          {"points", map.points.size()},
          {"counts", countsJson(map, false)},
          {"no_slip_counts", countsJson(map, true)},
          {"lcp_counts_by_mu_type", lcpCountsJson(map)},
          {"boundaries", boundaries},
          {"reference", referenceJson(map)}};
}

}  // namespace gaitopt::gaits
