#include "report/inspect_report.hpp"

#include <cmath>
#include <vector>

#include "dynamics/energy.hpp"
#include "dynamics/kinematics.hpp"
#include "dynamics/ssp_dynamics.hpp"

namespace gaitopt::report {
namespace {

using dynamics::Model;
using nlohmann::ordered_json;

template <class Derived>
ordered_json vectorJson(const Eigen::MatrixBase<Derived>& v) {
  std::vector<double> out(static_cast<size_t>(v.size()));
  for (Eigen::Index i = 0; i < v.size(); ++i)
    out[static_cast<size_t>(i)] = v(i) + 0.0;  // + 0.0 prints -0.0 as 0
  return out;
}

ordered_json matrixJson(const MatD& m) {
  ordered_json rows = ordered_json::array();
  for (Eigen::Index r = 0; r < m.rows(); ++r) rows.push_back(vectorJson(m.row(r).transpose()));
  return rows;
}

ordered_json linksJson(const Model& model) {
  ordered_json links = ordered_json::array();
  for (const auto& l : model.links())
    links.push_back({{"name", l.name},
                     {"mass", l.mass},
                     {"inertia", l.inertia},
                     {"length", l.length},
                     {"com", l.com},
                     {"continues", l.continues}});
  return links;
}

ordered_json jointsJson(const Model& model) {
  ordered_json joints = ordered_json::array();
  for (const auto& j : model.joints())
    joints.push_back({{"name", j.name},
                      {"actuated", j.actuated},
                      {"torque_limit", j.torque_limit},
                      {"velocity_limit", j.velocity_limit}});
  return joints;
}

ordered_json stateJson(const gaits::ChainState& s) {
  return {{"theta", vectorJson(s.theta)},
          {"dtheta", vectorJson(s.dtheta)},
          {"ddtheta", vectorJson(s.ddtheta)}};
}

/// Position and velocity relative to the stance tip B of the chain point with weights `w`.
ordered_json chainPointJson(const dynamics::ChainPoint& w, const gaits::ChainState& s) {
  return {{"position", vectorJson(dynamics::pointPosition(w, s.theta))},
          {"velocity", vectorJson(dynamics::pointVelocity(w, s.theta, s.dtheta))}};
}

/// D, H dtheta, G and the SSP inverse-dynamics joint torques (Mu 2.7, 2.43).
void addDynamics(ordered_json& out, const Model& model, const gaits::ChainState& s) {
  out["D"] = matrixJson(dynamics::massMatrix(model, s.theta));
  out["H_dtheta"] = vectorJson(dynamics::coriolis(model, s.theta, s.dtheta));
  out["G"] = vectorJson(dynamics::gravityVector(model, s.theta));
  out["tau"] = vectorJson(dynamics::sspInverseDynamics(model, s.theta, s.dtheta, s.ddtheta));
  out["kinetic_energy"] = dynamics::kineticEnergy(model, s.theta, s.dtheta);
  out["potential_energy"] = dynamics::potentialEnergy(model, s.theta);
}

void addKinematics(ordered_json& out, const Model& model, const gaits::ChainState& s) {
  out["com"] = chainPointJson(model.totalComWeights(), s);
  out["swing_tip"] = chainPointJson(model.tipWeights(), s);
  out["hip"] = chainPointJson(model.hipWeights(), s);
  // Link segments from proximal joint to distal end, for stick figures.
  ordered_json segments = ordered_json::array();
  for (int i = 0; i < model.nLinks(); ++i) {
    const Vec2d start = dynamics::pointPosition(model.jointWeights(i), s.theta);
    const Vec2d end =
        start + model.link(i).length * Vec2d(std::sin(s.theta(i)), std::cos(s.theta(i)));
    segments.push_back(
        {{"name", model.link(i).name}, {"start", vectorJson(start)}, {"end", vectorJson(end)}});
  }
  out["link_segments"] = segments;
}

}  // namespace

ordered_json inspectReport(const Model& model, const gaits::ChainState& state) {
  ordered_json out = {{"robot", model.name()},           {"n_links", model.nLinks()},
                      {"total_mass", model.totalMass()}, {"gravity", model.gravity()},
                      {"friction", model.friction()},    {"links", linksJson(model)},
                      {"joints", jointsJson(model)},     {"state", stateJson(state)}};
  addDynamics(out, model, state);
  addKinematics(out, model, state);
  return out;
}

}  // namespace gaitopt::report
