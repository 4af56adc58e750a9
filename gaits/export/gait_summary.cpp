#include "gaits/export/gait_summary.hpp"

#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "config/units.hpp"
#include "gaits/export/consistency.hpp"
#include "gaits/export/metrics.hpp"
#include "io/output/checked_write.hpp"

namespace gaitopt::gaits {
namespace {

using nlohmann::ordered_json;

ordered_json robotJson(const dynamics::Model& model) {
  ordered_json links = ordered_json::array();
  for (const auto& l : model.links())
    links.push_back({{"name", l.name}, {"length", l.length}, {"continues", l.continues}});
  ordered_json joints = ordered_json::array();
  for (const auto& j : model.joints()) joints.push_back({{"name", j.name}});
  // The foot the ZMP margins were taken against.
  return {{"links", links}, {"joints", joints}, {"foot", footJson(model.foot())}};
}

double costOf(const std::string& type, double work, double torque_sq, double cot) {
  if (type == "abs_work") return work;
  if (type == "torque_squared") return torque_sq;
  if (type == "cost_of_transport") return cot;
  throw std::invalid_argument("unknown cost_type '" + type + "'");
}

}  // namespace

ordered_json footJson(const dynamics::Foot& foot) {
  return {{"heel", foot.heel}, {"toe", foot.toe}};
}

ordered_json postureJson(const Trajectory& traj, const dynamics::Model& model) {
  const Posture upright = posture(traj, model);
  return {{"max_torso_lean", upright.torso_lean / kDeg},
          {"max_stance_knee_flexion", upright.stance_knee / kDeg},
          {"max_swing_knee_flexion", upright.swing_knee / kDeg}};
}

ordered_json gaitSummary(const Trajectory& traj, const dynamics::Model& model,
                         const SummaryContext& context) {
  const double work = absoluteWork(traj);
  const double torque_sq = torqueSquaredIntegral(traj);
  const double cot = costOfTransport(traj, model);
  ordered_json phases = ordered_json::array();
  for (const auto& [phase, duration] : traj.phaseDurations())
    phases.push_back({{"name", toString(phase)}, {"duration", duration}});
  const Eigen::VectorXd peak = peakTorque(traj);
  ordered_json s = {
      {"robot", model.name()},
      {"config", context.config},
      {"status", context.status},
      {"iterations", context.iterations},
      {"wall_time_s", context.wall_time_s},
      {"callback_time_s", context.callback_time_s},
      {"cost", costOf(context.cost_type, work, torque_sq, cot)},
      {"cost_type", context.cost_type},
      {"step_length", traj.stepLength()},
      {"duration", traj.duration()},
      {"speed", traj.stepLength() / traj.duration()},
      {"phases", phases},
      {"energy_J", work},
      {"torque_squared", torque_sq},
      {"cost_of_transport", cot},
      {"peak_torque", std::vector<double>(peak.data(), peak.data() + peak.size())},
      {"min_normal_force", minNormalForce(traj)},
      {"max_friction_ratio", maxFrictionRatio(traj)},
      {"min_zmp_margin", minZmpMargin(traj, model)},
      {"impact_energy_loss_J", impactEnergyLoss(traj, model)},
      {"touchdown_velocity_jump", touchdownVelocityJump(traj, model)},
      {"max_defect", maxDynamicsResidual(traj, model)},
      {"periodicity_error", periodicityError(traj, model)},
      {"friction", model.friction()},
      {"slope_rad", model.slope()},  // ground inclination, > 0 uphill (dynamics/model.hpp)
      {"total_mass", model.totalMass()},
  };
  s["posture_deg"] = postureJson(traj, model);
  s.update(robotJson(model));
  return s;
}

void writeJsonFile(const nlohmann::ordered_json& json, const std::string& path) {
  io::writeFileAtomically(path, json.dump(2) + '\n');
}

}  // namespace gaitopt::gaits
