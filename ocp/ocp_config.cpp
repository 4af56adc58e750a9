#include "ocp/ocp_config.hpp"

#include <cmath>
#include <filesystem>
#include <numbers>

#include "config/yaml_reader.hpp"

namespace gaitopt::ocp {
namespace {

using config::YamlReader;

std::string relativeTo(const std::string& file, const std::string& path) {
  const std::filesystem::path p(path);
  return p.is_absolute() ? path : (std::filesystem::path(file).parent_path() / p).string();
}

PhaseConfig readPhase(const YamlReader& r) {
  r.allowOnly({"name", "duration", "segments"});
  PhaseConfig p;
  p.name = r.choice("name", {"SSP", "DSP"});
  p.duration = r.number("duration", config::inRange(0.01, 10.0, "[s]"));
  const double segments = r.number("segments", config::inRange(1, 1000, "(whole number)"));
  if (segments != std::floor(segments)) r.fail("segments", "expected a whole number of segments");
  p.segments = static_cast<int>(segments);
  return p;
}

void readConstraints(const YamlReader& r, OcpConfig& c) {
  r.allowOnly({"torque_limits", "knee_limits", "angle_range", "rate_limit", "swing_descends",
               "trailing_lifts", "ground_contact", "zmp", "clearance"});
  c.ground_contact = r.booleanOr("ground_contact", true);
  c.zmp = r.booleanOr("zmp", true);
  c.clearance = r.numberOr("clearance", -1.0, config::inRange(-1.0, 1.0, "[m] (negative: off)"));
  c.torque_limits = r.booleanOr("torque_limits", true);
  c.knee_limits = r.booleanOr("knee_limits", true);
  c.angle_range = r.numberOr("angle_range", 0.0, config::inRange(0, std::numbers::pi, "[rad]"));
  c.rate_limit = r.numberOr("rate_limit", 0.0, config::inRange(0, 100, "[rad/s]"));
  c.swing_descends = r.booleanOr("swing_descends", true);
  c.trailing_lifts = r.booleanOr("trailing_lifts", true);
}

void readSolver(const YamlReader& r, SolverOptions& s) {
  r.allowOnly({"tolerance", "max_iterations", "hessian", "print_level", "mu_strategy", "mu_init"});
  if (r.has("mu_strategy")) s.mu_strategy = r.choice("mu_strategy", {"monotone", "adaptive"});
  s.mu_init = r.numberOr("mu_init", s.mu_init, config::inRange(1e-12, 1e3, ""));
  s.tolerance = r.numberOr("tolerance", s.tolerance, config::inRange(1e-14, 1e-1, ""));
  s.max_iterations =
      static_cast<int>(r.numberOr("max_iterations", s.max_iterations, config::inRange(1, 1e5, "")));
  if (r.has("hessian")) s.hessian = r.choice("hessian", {"exact", "limited-memory"});
  s.print_level = static_cast<int>(r.numberOr("print_level", 0, config::inRange(0, 12, "")));
}

}  // namespace

OcpConfig loadOcpConfig(const std::string& path) {
  const YamlReader root = YamlReader::fromFile(path);
  root.allowOnly({"name", "description", "robot", "initial_guess", "step_length", "phases",
                  "scheme", "impact", "cost", "torque_regularization", "constraints", "solver"});
  OcpConfig c;
  c.name = root.string("name");
  root.stringOr("description", "");
  c.robot_path = relativeTo(path, root.string("robot"));
  c.guess_gait_path = relativeTo(path, root.string("initial_guess"));
  c.step_length = root.number("step_length", config::inRange(0.01, 5.0, "[m]"));
  for (const auto& item : root.list("phases")) c.phases.push_back(readPhase(item));
  if (c.phases.front().name != "SSP" || c.phases.size() > 2 ||
      (c.phases.size() == 2 && c.phases.back().name != "DSP"))
    root.fail("phases", "expected [SSP] or [SSP, DSP]");
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
  c.cost = root.choice("cost", {"torque_squared", "abs_work"});
  c.torque_regularization = root.numberOr("torque_regularization", c.torque_regularization,
                                          config::inRange(0, 1e3, "(weight of sum tau^2)"));
  if (root.has("constraints")) readConstraints(root.map("constraints"), c);
  if (root.has("solver")) readSolver(root.map("solver"), c.solver);
  return c;
}

}  // namespace gaitopt::ocp
