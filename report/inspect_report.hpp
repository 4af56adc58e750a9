#pragma once
/// @file inspect_report.hpp
/// The JSON document `gaitopt inspect` prints: a robot's parameters and every dynamics quantity
/// at one chain state (keys in a fixed order, SI units, full double precision).
#include <nlohmann/json.hpp>

#include "dynamics/model.hpp"
#include "gaits/trajectory/state_file.hpp"

namespace gaitopt::report {

/// Keys: robot, n_links, total_mass, gravity, friction, links, joints, state, D, H_dtheta, G,
/// tau, kinetic_energy, potential_energy, com, swing_tip, hip.
nlohmann::ordered_json inspectReport(const dynamics::Model& model, const gaits::ChainState& state);

}  // namespace gaitopt::report
