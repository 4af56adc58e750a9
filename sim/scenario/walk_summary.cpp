#include "sim/scenario/walk_summary.hpp"

#include <cmath>
#include <vector>

#include "gaits/export/gait_summary.hpp"

namespace gaitopt::sim {
namespace {

/// The gait sensitivity norm of a push (poincare.hpp, Hobbelen and Wisse 2007); null values
/// when the cycle is not stable.
nlohmann::ordered_json gaitSensitivityJson(const PoincareAnalysis& p) {
  const auto number = [](double v) {
    return std::isfinite(v) ? nlohmann::ordered_json(v) : nlohmann::ordered_json();
  };
  return {
      {"disturbance", "push: horizontal hip impulse [N s], 0.1 s pulse from mid single support"},
      {"norm", number(p.gait_sensitivity_norm)},
      {"step_duration_s_per_Ns", number(p.gait_sensitivity_per_indicator(0))},
      {"step_advance_m_per_Ns", number(p.gait_sensitivity_per_indicator(1))}};
}

nlohmann::ordered_json poincareJson(const std::optional<PoincareAnalysis>& p) {
  nlohmann::ordered_json j;
  if (!p) {
    j["poincare_max_multiplier"] = nullptr;
    j["poincare_multipliers"] = nullptr;
    return j;
  }
  if (!p->ok) {
    j["poincare_max_multiplier"] = nullptr;
    j["poincare_multipliers"] = nullptr;
    j["poincare_failure"] = p->failure;
    return j;
  }
  auto multipliers = nlohmann::ordered_json::array();
  for (const auto& z : p->multipliers) multipliers.push_back({z.real(), z.imag()});
  j["poincare_max_multiplier"] = p->max_multiplier;
  j["poincare_multipliers"] = multipliers;
  j["poincare_fixed_point_residual"] = p->fixed_point_residual;
  j["poincare_section_clock_s"] = p->section_clock;
  j["gait_sensitivity"] = gaitSensitivityJson(*p);
  return j;
}

/// HZD's restricted Poincare map (sim/studies/hzd_poincare.hpp): analytic, and measured on the
/// walk.
nlohmann::ordered_json hzdJson(const ScenarioResult& r) {
  const RestrictedMap& a = *r.hzd_map;
  nlohmann::ordered_json j{
      {"phase_weights", std::vector<double>(a.phase_weights.begin(), a.phase_weights.end())},
      {"phase_plus", a.phi_plus},
      {"phase_minus", a.phi_minus},
      {"restricted_multiplier", a.multiplier},
      {"delta_zero", a.delta},
      {"v_zero_minus", a.v_minus},
      {"v_zero_max", a.v_max},
      {"zeta_minus_fixed_point", a.zeta_minus},
      {"phase_rate_at_touchdown", a.phidot_minus},
      {"hybrid_zero_dynamics_walk", a.walks}};
  if (r.hzd_measured && r.hzd_measured->ok)
    j["restricted_multiplier_measured"] = r.hzd_measured->multiplier;
  else if (r.hzd_measured)
    j["restricted_multiplier_measured_failure"] = r.hzd_measured->failure;
  return j;
}

/// Mean step length and duration over the completed steps.
nlohmann::ordered_json gaitJson(const WalkResult& w) {
  if (w.steps_completed == 0) return {{"mean_step_length", nullptr}, {"mean_speed", nullptr}};
  const WalkTotals total = completedTotals(w);
  return {{"mean_step_length", total.distance / w.steps_completed},
          {"mean_step_duration", total.duration / w.steps_completed},
          {"mean_speed", total.distance / total.duration}};
}

/// Slip per step and the stance foot's CoP (contact_rules.hpp). The CoP margin is that of the
/// ankle torque the controller asked for: negative when it left the foot (then saturated or a
/// foot rotation); null without an actuated ankle.
nlohmann::ordered_json contactJson(const WalkResult& w) {
  auto slip = nlohmann::ordered_json::array();
  for (const StepResult& s : w.steps) slip.push_back(s.slip);
  nlohmann::ordered_json j{{"slip_per_step_m", slip}, {"max_slip_m", w.max_slip}};
  if (std::isfinite(w.min_cop_margin))
    j["min_cop_margin_m"] = w.min_cop_margin;
  else
    j["min_cop_margin_m"] = nullptr;
  j["cop_saturated_time_s"] = w.cop_saturated_time;
  j["max_friction_ratio"] = w.max_friction_ratio;
  j["max_foot_tilt_rad"] = w.max_foot_tilt;
  // The rigid ground's swing tip below the ground (hybrid_walk.hpp StepResult); null on the
  // grounds that model that contact.
  if (std::isnan(w.max_tip_penetration))
    j["max_tip_penetration_m"] = nullptr;
  else
    j["max_tip_penetration_m"] = w.max_tip_penetration;
  return j;
}

}  // namespace

nlohmann::ordered_json walkSummary(const ScenarioSettings& settings, const ReferenceFolder& ref,
                                   const Scenario& s, const dynamics::Model& plant,
                                   const ScenarioResult& r) {
  nlohmann::ordered_json j{{"robot", ref.model.name()}, {"robot_file", ref.robot_path}};
  j.update(scenarioJson(settings, s));
  j["slope_rad"] = plant.slope();  // the reference's, which the walk is on
  j["friction"] = plant.friction();
  j["foot"] = gaits::footJson(plant.foot());  // the plant's, as walked
  j["steps_completed"] = r.walk.steps_completed;
  j["fell"] = r.walk.fell;
  j["failure"] = r.walk.failure;
  j["max_tracking_error"] = r.walk.max_tracking_error;
  j.update(gaitJson(r.walk));
  j.update(contactJson(r.walk));
  j.update(poincareJson(r.poincare));
  if (r.hzd_map) j["hzd"] = hzdJson(r);
  j["wall_time_s"] = r.wall_time_s;
  return j;
}

}  // namespace gaitopt::sim
