#include "ocp/problem/ocp_config.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <stdexcept>
#include <tuple>
#include <utility>

#include <fmt/format.h>

#include "config/config_path.hpp"
#include "config/yaml_reader.hpp"
#include "dynamics/model_variation.hpp"
#include "dynamics/robot_files/robot_config.hpp"

namespace gaitopt::ocp {
namespace {

using config::YamlReader;

/// The file `value` of `key` names, relative to the config's folder. @throws ConfigError naming
/// the config and the key when there is no such file.
std::string fileOfKey(const YamlReader& r, const std::string& key, const std::string& value,
                      const std::string& config_path) {
  std::string file = config::besideConfig(config_path, value);
  std::error_code ec;
  if (!std::filesystem::is_regular_file(file, ec))
    r.fail(key,
           fmt::format("no file '{}' (read relative to the config's folder: {})", value, file));
  return file;
}

PhaseConfig readPhase(const YamlReader& r) {
  r.allowOnly(
      {"name", "duration", "duration_min", "duration_max", "segments", "mesh", "first_segment"});
  PhaseConfig p;
  p.name = r.choice("name", {"SSP", "DSP"});
  p.duration = r.number("duration", config::inRange(0.01, 10.0, "[s]"));
  if (r.has("duration_min") || r.has("duration_max")) {
    p.duration_min =
        r.number("duration_min", config::inRange(0.01, p.duration, "[s], <= duration"));
    p.duration_max =
        r.number("duration_max", config::inRange(p.duration, 10.0, "[s], >= duration"));
  }
  p.segments = static_cast<int>(r.number("segments", config::wholeInRange(1, 1000, "")));
  if (r.has("mesh")) {  // segment boundaries as fractions of the phase, e.g. finer after impact
    p.mesh = r.numbers("mesh", config::inRange(0, 1, "(fraction of the phase)"));
    try {
      PhaseLayout{.segments = p.segments, .mesh = p.mesh}.validate();
    } catch (const std::invalid_argument& e) {
      r.fail("mesh",
             fmt::format("{} ({} segments: {} fractions)", e.what(), p.segments, p.segments + 1));
    }
  }
  if (r.has("first_segment")) {
    if (r.has("mesh")) r.fail("first_segment", "give either mesh or first_segment, not both");
    if (p.segments < 2) r.fail("first_segment", "needs at least 2 segments");
    p.first_segment =
        r.number("first_segment", config::inRange(1e-3, 0.999, "(fraction of the phase, < 1)"));
  }
  return p;
}

/// A step duration fixes SSP + DSP; it must be reachable within the phases' bounds.
void checkStepDuration(const YamlReader& root, const OcpConfig& c) {
  double lo = 0, hi = 0;
  for (const auto& p : c.phases) {
    lo += p.freeDuration() ? p.duration_min : p.duration;
    hi += p.freeDuration() ? p.duration_max : p.duration;
  }
  if (lo == hi)
    root.fail("step_duration", "needs a phase of free duration (duration_min/max) to share it");
  if (c.step_duration < lo || c.step_duration > hi)
    root.fail("step_duration", fmt::format("expected a value in [{}, {}] s that free phase "
                                           "durations (duration_min/max) can reach",
                                           lo, hi));
}

ClearanceProfile readClearance(const YamlReader& r) {
  r.allowOnly({"peak", "shape"});
  ClearanceProfile p{.enabled = true};
  p.peak = r.number("peak", config::inRange(0, 1, "[m]"));
  p.shape = r.choice("shape", {"sine_squared", "quartic"}) == "quartic"
                ? ClearanceProfile::Shape::kQuartic
                : ClearanceProfile::Shape::kSineSquared;
  return p;
}

const std::vector<std::string> kConstraintKeys{"torque_limits",
                                               "knee_limits",
                                               "angle_range",
                                               "rate_limit",
                                               "joint_velocity_limits",
                                               "swing_descends",
                                               "trailing_lifts",
                                               "ground_contact",
                                               "impact_friction",
                                               "zmp",
                                               "clearance",
                                               "friction_margin",
                                               "impulse_friction_margin",
                                               "zmp_margin",
                                               "min_normal_force",
                                               "dsp_reduced_coordinates",
                                               "jerk_limit",
                                               "jerk_jump_limit",
                                               "torque_rate_limit",
                                               "interior_contact",
                                               "max_knee_flexion",
                                               "min_trailing_knee_flexion"};

/// `min_trailing_knee_flexion`: a bend of the trailing knee through the double support, inside
/// the stance knee's own upper bound.
void readTrailingKneeFlexion(const YamlReader& r, OcpConfig& c) {
  const char* key = "min_trailing_knee_flexion";
  if (!r.has(key)) return;
  if (!c.knee_limits) r.fail(key, "a knee flexion bound needs knee_limits: true");
  c.min_trailing_knee_flexion = r.number(key, config::angleInRange(0, std::numbers::pi / 2));
  if (c.min_trailing_knee_flexion >= c.max_stance_knee_flexion)
    r.fail(key, "must be below max_knee_flexion's stance bound");
}

void readConstraints(const YamlReader& r, OcpConfig& c) {
  r.allowOnly(kConstraintKeys);
  c.ground_contact = r.booleanOr("ground_contact", true);
  c.impact_friction = r.booleanOr("impact_friction", true);
  c.zmp = r.booleanOr("zmp", true);
  c.friction_margin = r.numberOr("friction_margin", 0.0, config::inRange(0, 1, "(of mu)"));
  if (r.has("impulse_friction_margin"))
    c.impulse_friction_margin =
        r.number("impulse_friction_margin", config::inRange(0, 1, "(of mu)"));
  c.zmp_margin = r.numberOr("zmp_margin", 0.0, config::inRange(0, 1, "[m]"));
  if (c.zmp_margin > 0 && !c.zmp) r.fail("zmp_margin", "a ZMP margin needs zmp: true");
  c.min_normal_force = r.numberOr("min_normal_force", 0.0, config::inRange(0, 1e4, "[N]"));
  if (c.min_normal_force > 0 && !c.ground_contact)
    r.fail("min_normal_force", "a least normal force needs ground_contact: true");
  const double interior =
      r.numberOr("interior_contact", 0, config::inRange(0, 32, "(sub-intervals)"));
  if (interior != 0 && (interior < 4 || std::fmod(interior, 2.0) != 0))
    r.fail("interior_contact", "expected 0 or an even number of sub-intervals >= 4");
  if (interior > 0 && !c.ground_contact)
    r.fail("interior_contact", "interior contact rows need ground_contact: true");
  c.interior_contact = static_cast<int>(interior);
  if (r.has("clearance")) c.clearance = readClearance(r.map("clearance"));
  c.torque_limits = r.booleanOr("torque_limits", true);
  c.knee_limits = r.booleanOr("knee_limits", true);
  if (r.has("max_knee_flexion")) {
    if (!c.knee_limits) r.fail("max_knee_flexion", "a knee flexion bound needs knee_limits: true");
    const std::vector<double> v =
        r.numbers("max_knee_flexion", config::angleInRange(0, std::numbers::pi));
    if (v.size() != 2)
      r.fail("max_knee_flexion", fmt::format("expected [stance, swing], got {} numbers", v.size()));
    c.max_stance_knee_flexion = v[0];
    c.max_swing_knee_flexion = v[1];
  }
  readTrailingKneeFlexion(r, c);
  c.angle_range = r.numberOr("angle_range", 0.0, config::inRange(0, std::numbers::pi, "[rad]"));
  c.rate_limit = r.numberOr("rate_limit", 0.0, config::inRange(0, 100, "[rad/s]"));
  c.jerk_limit = r.numberOr("jerk_limit", 0.0, config::inRange(0, 1e7, "[rad/s^3]"));
  c.jerk_jump_limit = r.numberOr("jerk_jump_limit", 0.0, config::inRange(0, 1e7, "[rad/s^3]"));
  c.torque_rate_limit = r.numberOr("torque_rate_limit", 0.0, config::inRange(0, 1e7, "[N m/s]"));
  c.joint_velocity_limits = r.booleanOr("joint_velocity_limits", false);
  c.swing_descends = r.booleanOr("swing_descends", true);
  c.trailing_lifts = r.booleanOr("trailing_lifts", true);
  c.dsp_reduced_coordinates = r.booleanOr("dsp_reduced_coordinates", false);
}

/// The margins must leave a foot (under half its length, heel + toe) and a friction cone (under
/// the robot's mu), both read from the robot file.
void checkMarginsFitTheRobot(const YamlReader& r, const OcpConfig& c,
                             const dynamics::Model& robot) {
  const dynamics::Foot foot = robot.foot();
  const double half = (foot.heel + foot.toe) / 2;
  if (c.zmp_margin > 0 && !(c.zmp_margin < half))
    r.fail("zmp_margin", fmt::format("expected less than half the robot's foot, (heel {} + toe {}) "
                                     "/ 2 = {} m, got {} m",
                                     foot.heel, foot.toe, half, c.zmp_margin));
  const auto checkCone = [&](const std::string& key, double margin) {
    if (!(margin < robot.friction()))
      r.fail(key, fmt::format("expected less than the robot's friction coefficient {} (the margin "
                              "narrows its cone), got {}",
                              robot.friction(), margin));
  };
  checkCone("friction_margin", c.friction_margin);
  if (c.impulse_friction_margin) checkCone("impulse_friction_margin", *c.impulse_friction_margin);
  // As the problem's builders (phase_builder.cpp, interior_contact.cpp) would refuse them, but
  // named by key.
  const bool knee_bound = c.max_stance_knee_flexion < kInf || c.max_swing_knee_flexion < kInf ||
                          c.min_trailing_knee_flexion > 0;
  if (knee_bound && !(c.knee_limits && robot.legLinks() == 2))
    r.fail(r.has("max_knee_flexion") ? "max_knee_flexion" : "min_trailing_knee_flexion",
           robot.legLinks() == 2 ? "a knee flexion bound needs knee_limits: true"
                                 : "a knee flexion bound, but the robot's legs have no knees");
  const bool free_duration = std::any_of(c.phases.begin(), c.phases.end(),
                                         [](const PhaseConfig& p) { return p.freeDuration(); });
  if (c.interior_contact > 0 && (c.scheme != Scheme::kHermiteSimpson || free_duration))
    r.fail("interior_contact", "needs scheme: hermite_simpson and phases of fixed duration");
}

/// A [min, max] pair under `key`, each value checked; min > max is an error naming the key.
std::pair<double, double> readRange(const YamlReader& r, const std::string& key,
                                    const config::NumberCheck& check) {
  const std::vector<double> v = r.numbers(key, check);
  if (v.size() != 2) r.fail(key, fmt::format("expected [min, max], got {} numbers", v.size()));
  if (v[0] > v[1]) r.fail(key, fmt::format("expected min <= max, got [{}, {}]", v[0], v[1]));
  return {v[0], v[1]};
}

StrikeDesign readTouchdown(const YamlReader& r) {
  r.allowOnly({"normal_velocity", "angle"});
  StrikeDesign d{.enabled = true};
  std::tie(d.normal_min, d.normal_max) =
      readRange(r, "normal_velocity", config::inRange(0, 5, "[m/s], downward"));
  if (r.has("angle")) {
    d.angle = true;
    std::tie(d.angle_min, d.angle_max) =
        readRange(r, "angle", config::angleInRange(0, std::numbers::pi));
    // The angle of a tip at rest is undefined (rows that bound it degenerate at V_e = 0).
    if (!(d.normal_min > 0))
      r.fail("normal_velocity", "a bounded strike angle needs a normal velocity min > 0");
  }
  return d;
}

CostWeights readCost(const YamlReader& r) {
  r.allowOnly({"torque_squared", "abs_work", "cost_of_transport"});
  const auto weight = config::inRange(0, 1e6, "(weight)");
  CostWeights w;
  w.torque_squared = r.numberOr("torque_squared", 0.0, weight);
  w.abs_work = r.numberOr("abs_work", 0.0, weight);
  w.cost_of_transport = r.numberOr("cost_of_transport", 0.0, weight);
  if (w.torque_squared + w.abs_work + w.cost_of_transport == 0)
    r.fail("torque_squared", "expected at least one positive cost weight");
  return w;
}

MeshRefinement readRefinement(const YamlReader& r) {
  r.allowOnly({"tolerance", "max_rounds"});
  MeshRefinement m;
  m.tolerance = r.number("tolerance", config::inRange(1e-9, 1e3, "[N m s]"));
  m.max_rounds =
      static_cast<int>(r.numberOr("max_rounds", m.max_rounds, config::wholeInRange(1, 10, "")));
  return m;
}

void readSolver(const YamlReader& r, SolverOptions& s) {
  r.allowOnly({"tolerance", "max_iterations", "hessian", "jacobian", "linear_solver", "print_level",
               "mu_strategy", "mu_init", "bound_push", "bound_frac", "mumps_pivot_order",
               "nlp_scaling_method", "constraint_tolerance", "bound_mult_init_method",
               "constr_mult_init_max", "min_refinement_steps"});
  if (r.has("mu_strategy")) s.mu_strategy = r.choice("mu_strategy", {"monotone", "adaptive"});
  s.mu_init = r.numberOr("mu_init", s.mu_init, config::inRange(1e-12, 1e3, ""));
  s.tolerance = r.numberOr("tolerance", s.tolerance, config::inRange(1e-14, 1e-1, ""));
  s.constraint_tolerance =
      r.numberOr("constraint_tolerance", s.constraint_tolerance, config::inRange(1e-14, 1e-1, ""));
  if (r.has("bound_mult_init_method"))
    s.bound_mult_init_method = r.choice("bound_mult_init_method", {"constant", "mu-based"});
  s.constr_mult_init_max =
      r.numberOr("constr_mult_init_max", s.constr_mult_init_max, config::inRange(0, 1e20, ""));
  s.min_refinement_steps = static_cast<int>(
      r.numberOr("min_refinement_steps", s.min_refinement_steps, config::wholeInRange(0, 10, "")));
  s.max_iterations = static_cast<int>(
      r.numberOr("max_iterations", s.max_iterations, config::wholeInRange(1, 1e5, "")));
  if (r.has("hessian")) s.hessian = r.choice("hessian", {"exact", "limited-memory"});
  s.mumps_pivot_order = static_cast<int>(
      r.numberOr("mumps_pivot_order", s.mumps_pivot_order, config::wholeInRange(0, 7, "")));
  if (r.has("nlp_scaling_method"))
    s.nlp_scaling_method = r.choice("nlp_scaling_method", {"gradient-based", "none"});
  if (r.has("jacobian")) s.jacobian = r.choice("jacobian", {"exact", "finite-difference-values"});
  if (r.has("linear_solver")) s.linear_solver = r.choice("linear_solver", {"mumps", "ldl"});
  s.bound_push = r.numberOr("bound_push", s.bound_push, config::inRange(1e-12, 0.5, ""));
  s.bound_frac = r.numberOr("bound_frac", s.bound_frac, config::inRange(1e-12, 0.5, ""));
  s.print_level = static_cast<int>(r.numberOr("print_level", 0, config::wholeInRange(0, 12, "")));
}

// The problem's shape (ocp/shape/shape_config.hpp): its keys sit beside the others at the root.
std::vector<std::string> withShapeKeys(std::vector<std::string> keys) {
  keys.insert(keys.end(), shapeKeys().begin(), shapeKeys().end());
  return keys;
}

/// The section, checked against the problem: the easy problem is the torque-squared one, and a
/// continuation mesh has a segment count per phase.
void readContinuationOf(const YamlReader& root, OcpConfig& c) {
  c.continuation = readContinuation(root.map("continuation"));
  if (!(c.cost.torque_squared > 0))
    root.fail("continuation",
              "a continuation starts from the torque-squared problem: expected "
              "cost.torque_squared > 0");
  const std::vector<int>& segments = c.continuation.mesh_segments;
  if (segments.empty()) return;
  if (segments.size() != c.phases.size())
    root.map("continuation")
        .map("mesh")
        .fail("segments", fmt::format("expected one count per phase ({}), got {}", c.phases.size(),
                                      segments.size()));
}

}  // namespace

std::vector<double> PhaseConfig::fractions() const {
  if (!mesh.empty() || first_segment <= 0 || segments < 2) return mesh;
  // Each segment at most kGrowth times the one before, else an equal share of what is left: a
  // jump in segment length is a jump in the export's jerk at the shared point, which 1 kHz
  // differences of the rates see (doubling after a 5 ms first segment: 0.97 % of the peak
  // acceleration; growing by 1.5: 0.91 %; results/dsp_coordinates.md).
  constexpr double kGrowth = 1.5;
  std::vector<double> f{0.0};
  double length = first_segment;
  for (int k = 0; k + 1 < segments; ++k, length *= kGrowth)
    f.push_back(f.back() + std::min(length, (1 - f.back()) / (segments - k)));
  f.push_back(1.0);
  return f;
}

std::string CostWeights::primary() const {
  if (cost_of_transport > 0) return "cost_of_transport";
  return abs_work > 0 ? "abs_work" : "torque_squared";
}

namespace {

/// The computed-torque law of the variants (ocp/shape/computed_torque_law.hpp) commands every
/// joint.
void checkFeedbackFitsTheRobot(const YamlReader& root, const OcpConfig& c,
                               const dynamics::Model& robot) {
  if (c.shape.feedback.law != FeedbackGains::Law::kComputedTorque) return;
  for (const auto& joint : robot.joints())
    if (!joint.actuated)
      root.map("variant_feedback")
          .fail("law", fmt::format("computed_torque commands every joint, and the robot's joint "
                                   "'{}' is passive: use law: joint_pd",
                                   joint.name));
}

}  // namespace

OcpConfig loadOcpConfig(const std::string& path, const std::vector<config::Override>& overrides) {
  const YamlReader root = YamlReader::fromFile(path, overrides);
  root.allowOnly(
      withShapeKeys({"name", "description", "robot", "initial_guess", "step_length", "phases",
                     "step_duration", "scheme", "impact", "cost", "mesh_refinement", "constraints",
                     "solver", "slope", "touchdown", "continuation"}));
  OcpConfig c;
  c.name = root.string("name");
  root.stringOr("description", "");
  c.robot_path = fileOfKey(root, "robot", root.string("robot"), path);
  const dynamics::Model robot = dynamics::loadRobot(c.robot_path);  // for the checks against it
  const std::string guess = root.string("initial_guess");
  if (guess != kStraightLegGuess) c.guess_gait_path = fileOfKey(root, "initial_guess", guess, path);
  c.step_length = root.number("step_length", config::inRange(0.01, 5.0, "[m]"));
  c.slope = root.numberOr(
      "slope", 0.0, config::angleInRange(-dynamics::kMaxConfigSlope, dynamics::kMaxConfigSlope));
  for (const auto& item : root.list("phases")) c.phases.push_back(readPhase(item));
  if (c.phases.front().name != "SSP" || c.phases.size() > 2 ||
      (c.phases.size() == 2 && c.phases.back().name != "DSP"))
    root.fail("phases", "expected [SSP] or [SSP, DSP]");
  if (c.guess_gait_path.empty() && c.phases.size() == 2)
    root.fail("phases", "the straight-leg guess builds steps without a DSP: expected [SSP]");
  c.step_duration = root.numberOr("step_duration", 0.0, config::inRange(0.02, 20.0, "[s]"));
  if (c.step_duration > 0) checkStepDuration(root, c);
  c.scheme = schemeFromString(root.choice("scheme", {"trapezoidal", "hermite_simpson"}));
  const std::string impact = root.choice("impact", {"single", "double", "impactless"});
  c.impact = impact == "single"   ? ImpactModel::kSingle
             : impact == "double" ? ImpactModel::kDouble
                                  : ImpactModel::kImpactless;
  if ((c.phases.size() == 2) == (c.impact == ImpactModel::kSingle))
    root.fail("impact", c.phases.size() == 2
                            ? "a step with a DSP needs a double or impactless touchdown"
                            : "a step without a DSP needs a single impact (the old stance tip "
                              "lifts off)");
  c.cost = readCost(root.map("cost"));
  if (root.has("mesh_refinement")) c.refinement = readRefinement(root.map("mesh_refinement"));
  if (root.has("constraints")) {
    readConstraints(root.map("constraints"), c);
    checkMarginsFitTheRobot(root.map("constraints"), c, robot);
  }
  if (root.has("touchdown")) {
    c.touchdown = readTouchdown(root.map("touchdown"));
    if (c.impact == ImpactModel::kImpactless)
      root.fail("touchdown",
                "a designed strike needs a rigid impact (single or double), not "
                "an impactless touchdown");
  }
  if (root.has("solver")) readSolver(root.map("solver"), c.solver);
  c.shape = readShapeConfig(root);  // the problem's shape (ocp/shape/shape_config.hpp)
  checkFeedbackFitsTheRobot(root, c, robot);
  if (root.has("continuation")) readContinuationOf(root, c);
  return c;
}

namespace {

/// The robot's mu less `margin` (the config key `key`). @throws std::invalid_argument when it
/// leaves no cone.
double narrowedFriction(const dynamics::Model& model, double margin, const std::string& key) {
  const double mu = model.friction() - margin;
  if (!(mu > 0))
    throw std::invalid_argument(key + " must be below the robot's friction coefficient");
  return mu;
}

}  // namespace

double frictionBound(const dynamics::Model& model, const OcpConfig& config) {
  return narrowedFriction(model, config.friction_margin, "friction_margin");
}

double impulseFrictionBound(const dynamics::Model& model, const OcpConfig& config) {
  if (!config.impulse_friction_margin) return frictionBound(model, config);
  return narrowedFriction(model, *config.impulse_friction_margin, "impulse_friction_margin");
}

dynamics::Foot marginFoot(const dynamics::Model& model, const OcpConfig& config) {
  const dynamics::Foot foot{model.foot().heel - config.zmp_margin,
                            model.foot().toe - config.zmp_margin};
  if (!(foot.heel + foot.toe > 0))
    throw std::invalid_argument("zmp_margin must be below half the robot's foot");
  return foot;
}

std::vector<std::string> ocpInputs(const OcpConfig& config) {
  return {config.robot_path, config.guess_gait_path};
}

dynamics::Model problemModel(const OcpConfig& config) {
  return dynamics::withSlope(dynamics::loadRobot(config.robot_path), config.slope);
}

double shortestStep(const OcpConfig& config) {
  if (config.step_duration > 0) return config.step_duration;
  double duration = 0;
  for (const PhaseConfig& p : config.phases)
    duration += p.freeDuration() ? p.duration_min : p.duration;
  return duration;
}

void requireReachable(const dynamics::Model& model, const OcpConfig& config,
                      const std::string& path) {
  double leg = 0;
  for (int i = 0; i < model.legLinks(); ++i) leg += model.link(i).length;
  if (config.step_length < 2 * leg) return;
  throw std::domain_error(fmt::format(
      "{}: key 'step_length': {:g} m is out of reach: the legs of robot '{}' ({:.4g} m each) "
      "span less than {:.4g} m",
      path, config.step_length, model.name(), leg, 2 * leg));
}

}  // namespace gaitopt::ocp
