#pragma once
/// @file scenario.hpp
/// One closed-loop experiment: a reference gait tracked by a controller on its nominal model,
/// driving a plant that may differ from it (Mu 2004 ch. 4 uncertainty, another friction), on
/// one of the three grounds, optionally pushed; and the sweep parameters that vary it.
#include <optional>
#include <string>
#include <vector>

#include "config/quantities.hpp"
#include "dynamics/model_variation.hpp"
#include "sim/contact/ground_model.hpp"
#include "sim/controllers/controller_registry.hpp"
#include "sim/studies/hzd_poincare.hpp"
#include "sim/studies/poincare.hpp"
#include "sim/walk/hybrid_walk.hpp"
#include "sim/walk/push.hpp"

namespace gaitopt::sim {

struct Scenario {
  std::string controller = kDefaultController;  ///< a name of controllers()
  TrackingGains gains;
  MuSlidingModeGains mu_gains;  ///< Table 4.2 of the scenario's uncertainty case
  double gain_scale = 1;        ///< bandwidth factor s: kp, K by s^2; kd, lambda by s
  dynamics::ParameterErrors parameter_errors;  ///< the plant's parameters are (1 + E) the nominal
  /// Mu's setting instead (sec. 4.3): the plant is nominal and the controller's model is
  /// (1 + E) the nominal, so the reference gait still fits the plant's geometry.
  bool errors_on_controller = false;
  std::optional<double> friction;  ///< the plant's mu, if not the robot's
  GroundModel ground = RigidGround{};
  std::optional<Push> push;
  ContactRules rules;  ///< failures and contact limits, the same on every ground
  int steps = 20;
  bool poincare = false;  ///< also the Poincare map (rigid ground only)
};

/// The plant-error interval mu_sliding_mode is meant to cover when its model is nominal: masses
/// and inertias 20 %, lengths and CoM offsets 5 %.
inline constexpr dynamics::ParameterErrors kPlantErrorBound{0.2, 0.2, 0.05, 0.05};

/// What mu_sliding_mode knows of its model's error (the true parameters within a factor (1 + b)
/// of its model's): in Mu's setting (errors on the controller, sec. 4.3) the bound of the errors
/// its model has, a case's or a --mass-error's or a sweep point's; else kPlantErrorBound.
dynamics::ParameterErrors uncertaintyBound(const Scenario& s);

/// The box mu_sliding_mode's bound describes: Mu's premise (its model overestimates the robot,
/// phi^ = (1 + E) phi, sec. 4.2) in Mu's setting, errors on the controller and none negative;
/// either way otherwise.
BoundSide muBoundSide(const Scenario& s);

struct ScenarioResult {
  WalkResult walk;
  std::optional<PoincareAnalysis> poincare;  ///< when asked for and the ground is rigid
  /// HZD only: the restricted map of the zero dynamics, analytic and (with poincare) measured.
  std::optional<RestrictedMap> hzd_map;
  std::optional<MeasuredRestrictedMap> hzd_measured;
  double wall_time_s = 0;
};

/// The plant the scenario simulates: the nominal model with the scenario's variations.
dynamics::Model scenarioPlant(const dynamics::Model& nominal, const Scenario& scenario);
/// The model the controller computes with.
dynamics::Model scenarioControllerModel(const dynamics::Model& nominal, const Scenario& scenario);

/// The scenario's controller on `model` (scenarioControllerModel's) for `ref`, with its gains at
/// its bandwidth. @throws std::invalid_argument for an unknown controller, a bad gain_scale, or
/// a model or reference the controller cannot drive.
std::unique_ptr<Controller> makeController(const dynamics::Model& model, const Reference& ref,
                                           const Scenario& scenario);

/// Walks the scenario. @throws std::invalid_argument for an unknown controller or bad values.
ScenarioResult runScenario(const dynamics::Model& nominal, const Reference& ref,
                           const Scenario& scenario, const WalkLog& log = {});

/// A parameter a stability sweep varies.
struct SweepParameter {
  config::Quantity quantity;  ///< name, unit and the values a sweep may take
  std::string meaning;
  double first, last;      ///< default range
  int count;               ///< default number of values
  bool geometric = false;  ///< values spaced by a constant ratio (over decades), not a step

  std::string name() const { return std::string(quantity.name); }
  std::string unit() const { return std::string(quantity.unit); }
};

/// push, mass_error, length_error, friction, stiffness, gain_scale.
const std::vector<SweepParameter>& sweepParameters();
/// @throws std::invalid_argument for an unknown name.
const SweepParameter& sweepParameter(const std::string& name);
/// The parameter's value in `scenario` (the nominal point of a sweep); NaN when it has none
/// (stiffness off a compliant ground: impedance, pad).
double sweepValue(const Scenario& scenario, const std::string& name);
/// Sets the parameter. @throws std::invalid_argument for an unknown name, or stiffness on a
/// ground that has none (rigid, LCP, DART).
void setSweepValue(Scenario& scenario, const std::string& name, double value);

}  // namespace gaitopt::sim
