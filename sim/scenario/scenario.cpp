#include "sim/scenario/scenario.hpp"

#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <typeinfo>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "sim/controllers/hzd_controller.hpp"
#include "sim/walk/ground_registry.hpp"
#include "sim/walk/walk.hpp"

namespace gaitopt::sim {
namespace {

TrackingGains scaledGains(TrackingGains g, double s) {
  if (!(std::isfinite(s) && s > 0))
    throw std::invalid_argument("gain_scale must be a positive number");
  g.kp *= s * s;
  g.kd *= s;
  g.lambda *= s;
  g.switching *= s * s;
  return g;
}

/// Mu's constants at bandwidth factor s: Lambda by s, the tanh slopes unchanged.
MuSlidingModeGains scaledGains(MuSlidingModeGains g, double s) {
  g.ssp_lambda *= s;
  g.dsp_lambda *= s;
  return g;
}

const std::vector<SweepParameter> kParameters{
    {config::kPush,
     "horizontal impulse on the hip, a 0.1 s pulse from mid single support of step 2", -15, 15, 31},
    {config::kMassError, "relative error of the masses and inertias (Mu e_m = e_I)", -0.5, 2.0, 26},
    {config::kLengthError, "relative error of the link lengths and CoM offsets (Mu e_l = e_d)",
     -0.3, 0.5, 17},
    {config::kFriction, "Coulomb coefficient of the ground", 0.05, 1.0, 20},
    // Both compliant grounds (CompliantGround settings) have a stiffness: the impedance ground's
    // Hunt-Crossley k and the pad's spring k.
    {config::kStiffness,
     "contact stiffness k of a compliant ground, damping scaled alike (impedance or pad ground "
     "only)",
     1e4, 1e9, 11, true},
    {config::kGainScale, "controller bandwidth factor (kp, K by s^2; kd, lambda by s)", 0.1, 3.0,
     30},
};

}  // namespace

dynamics::Model scenarioPlant(const dynamics::Model& nominal, const Scenario& s) {
  const dynamics::Model plant =
      s.errors_on_controller ? nominal : dynamics::perturbedModel(nominal, s.parameter_errors);
  return s.friction ? dynamics::withFriction(plant, *s.friction) : plant;
}

dynamics::Model scenarioControllerModel(const dynamics::Model& nominal, const Scenario& s) {
  return s.errors_on_controller ? dynamics::perturbedModel(nominal, s.parameter_errors) : nominal;
}

namespace {

/// HZD's restricted map on the controller's constraints: analytic, and measured on the plant.
void analyseHzd(const dynamics::Model& plant, const dynamics::Model& model,
                const HzdController& hzd, const Reference& ref, const Scenario& s,
                ScenarioResult& r) {
  r.hzd_map = restrictedMap(model, hzd.constraints());
  const auto* rigid = s.ground.getIf<RigidGround>();
  if (s.poincare && rigid && r.hzd_map->zeta_minus > 0)
    r.hzd_measured =
        measureRestrictedMap(plant, hzd, ref, hzd.constraints(),
                             r.hzd_map->multiplier * r.hzd_map->zeta_minus, rigid->integrator);
}

}  // namespace

BoundSide muBoundSide(const Scenario& s) {
  const auto& e = s.parameter_errors;
  const bool overestimates = e.mass >= 0 && e.inertia >= 0 && e.length >= 0 && e.com >= 0;
  return s.errors_on_controller && overestimates ? BoundSide::kOverestimated
                                                 : BoundSide::kEitherWay;
}

std::unique_ptr<Controller> makeController(const dynamics::Model& model, const Reference& ref,
                                           const Scenario& s) {
  const ControllerSetting setting{model,
                                  ref,
                                  scaledGains(s.gains, s.gain_scale),
                                  scaledGains(s.mu_gains, s.gain_scale),
                                  uncertaintyBound(s),
                                  muBoundSide(s)};
  return controllerEntry(s.controller).build(setting);
}

ScenarioResult runScenario(const dynamics::Model& nominal, const Reference& ref, const Scenario& s,
                           const WalkLog& log) {
  const auto start = std::chrono::steady_clock::now();
  const dynamics::Model plant = scenarioPlant(nominal, s);
  const dynamics::Model model = scenarioControllerModel(nominal, s);
  const std::unique_ptr<Controller> controller = makeController(model, ref, s);
  ScenarioResult r;
  if (const auto* hzd = dynamic_cast<const HzdController*>(controller.get()))
    analyseHzd(plant, model, *hzd, ref, s, r);
  r.walk = walk(plant, *controller, ref, s.ground, WalkPlan{s.steps, s.push, s.rules}, log);
  if (s.poincare) {
    if (const auto* rigid = s.ground.getIf<RigidGround>()) {
      PoincareOptions options;
      options.integrator = rigid->integrator;
      options.rules = s.rules;
      r.poincare = analysePoincare(plant, *controller, ref, options);
    }
  }
  r.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

const std::vector<SweepParameter>& sweepParameters() {
  return kParameters;
}

const SweepParameter& sweepParameter(const std::string& name) {
  for (const auto& p : kParameters)
    if (p.name() == name) return p;
  std::string known;
  for (const auto& p : kParameters) known += (known.empty() ? "" : ", ") + p.name();
  throw std::invalid_argument("unknown sweep parameter '" + name + "' (expected one of " + known +
                              ")");
}

double sweepValue(const Scenario& s, const std::string& name) {
  sweepParameter(name);
  if (name == "push") return s.push ? s.push->impulse(0) : 0.0;
  if (name == "mass_error") return s.parameter_errors.mass;
  if (name == "length_error") return s.parameter_errors.length;
  if (name == "gain_scale") return s.gain_scale;
  if (name == "friction") return s.friction.value_or(std::numeric_limits<double>::quiet_NaN());
  const auto* compliant = s.ground.getIf<CompliantGround>();
  return compliant ? compliant->contact.stiffness : std::numeric_limits<double>::quiet_NaN();
}

dynamics::ParameterErrors uncertaintyBound(const Scenario& s) {
  if (!s.errors_on_controller) return kPlantErrorBound;
  // The model's parameter is (1 + e) the plant's; the box [p / (1 + b), p (1 + b)] about the
  // model's p holds the plant's p / (1 + e) for b = e when e >= 0, and b = -e / (1 + e) when
  // the model underestimates (mu_sliding_mode.cpp's corners need b >= 0).
  const auto bound = [](double e) { return e >= 0 ? e : -e / (1 + e); };
  const dynamics::ParameterErrors& e = s.parameter_errors;
  return {bound(e.mass), bound(e.inertia), bound(e.length), bound(e.com)};
}

void setSweepValue(Scenario& s, const std::string& name, double value) {
  sweepParameter(name);
  if (name == "push") {
    Push push = s.push.value_or(Push{});
    // A walk that ends before the pushed step would report the push as survived.
    if (s.steps < push.step)
      throw std::invalid_argument(fmt::format(
          "the push comes in step {} (from mid single support); a walk of {} step(s) never "
          "meets it: walk at least {} steps (--steps)",
          push.step, s.steps, push.step));
    push.impulse = Vec2d(value, 0);
    s.push = push;
  } else if (name == "mass_error") {
    s.parameter_errors.mass = s.parameter_errors.inertia = value;
  } else if (name == "length_error") {
    s.parameter_errors.length = s.parameter_errors.com = value;
  } else if (name == "gain_scale") {
    s.gain_scale = value;
  } else if (name == "friction") {
    s.friction = value;
  } else if (auto* compliant = s.ground.getIf<CompliantGround>()) {
    // Damping with the stiffness, so alpha = 2c / (3k) and the restitution stay the same.
    compliant->contact.damping *= value / compliant->contact.stiffness;
    compliant->contact.stiffness = value;
  } else {
    // The grounds whose settings hold a stiffness, from the registry: a new compliant ground is
    // named here without a change.
    std::vector<std::string> compliant_grounds;
    for (const GroundEntry& e : grounds())
      if (e.settings == typeid(CompliantGround)) compliant_grounds.push_back("--ground " + e.name);
    throw std::invalid_argument(
        fmt::format("stiffness is swept on a compliant ground only ({}), not on the {} ground",
                    fmt::join(compliant_grounds, " or "), groundName(s.ground)));
  }
}

}  // namespace gaitopt::sim
