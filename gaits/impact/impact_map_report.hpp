#pragma once
/// @file impact_map_report.hpp
/// The files of `gaitopt impact-map`: impact_map.csv (one row per grid point) and summary.json
/// (counts per impact type and the type boundaries along each axis). Angles in degrees.
#include <string>

#include <nlohmann/json.hpp>

#include "dynamics/model.hpp"
#include "gaits/impact/impact_map.hpp"

namespace gaitopt::gaits {

/// Writes the CSV to path + ".tmp" and renames it when complete. Columns: step_length (tip
/// distance [m]), mu_SL (Mu's S_L = 2 step_length), knee_bias_deg, approach_angle_deg,
/// approach_speed, hip_height, type, P_lx, P_ly, P_rx, P_ry (double model), xdot_b, ydot_b, P_Sx,
/// P_Sy (single model), mu_L, mu_R, mu_S, double_no_slip, single_no_slip (0/1 at the robot's mu),
/// lcp_type (the families the complementarity law allows, dynamics::complementarityImpact).
/// @throws std::runtime_error when the file cannot be written.
void writeImpactMapCsv(const ImpactMap& map, const std::string& path);

/// Keys: robot, friction, approach_speed, grid, points, counts (per type), no_slip_counts,
/// lcp_counts_by_mu_type (per type of Mu's criterion, the points of each complementarity type),
/// boundaries (per axis and type change: lines, min, median, max of the boundary), reference
/// (the grid point nearest Mu's case 0.35 m, 15 deg, 90 deg and the type changes along each axis
/// through it).
nlohmann::ordered_json impactMapSummary(const ImpactMap& map, const dynamics::Model& model);

}  // namespace gaitopt::gaits
