#include <numbers>

#include <fmt/format.h>

#include "config/yaml_reader.hpp"
#include "dynamics/model.hpp"
#include "gaits/polynomial/gait_params.hpp"

namespace gaitopt::gaits {

GaitParams loadGait(const std::string& path, const std::vector<config::Override>& overrides) {
  using config::inRange;
  using config::positive;
  const auto root = config::YamlReader::fromFile(path, overrides);
  root.allowOnly({"name", "description", "step_length", "ssp_duration", "dsp_duration",
                  "swing_apex", "hip", "torso_angle", "knee", "slope"});
  GaitParams p;
  p.name = root.string("name");
  root.stringOr("description", "");
  p.step_length = root.number("step_length", inRange(0.01, 5.0, "[m] (tip distance at touchdown)"));
  p.ssp_duration = root.number("ssp_duration", inRange(0.01, 10.0, "[s]"));
  p.dsp_duration = root.number("dsp_duration", inRange(0.001, 10.0, "[s]"));

  const auto apex = root.map("swing_apex");
  apex.allowOnly({"x", "height"});
  // y_a, the quintic of (3.10)-(3.12) with zero slope at both ends and at the apex, is
  // tau^2 (1 - tau)^2 (p + q tau) in tau = t / T_S: it stays above the ground only while the apex
  // time lies in [0.4, 0.6] T_S, which x_a's cubic (3.7)-(3.11) maps to |S_m| <= 0.296 S
  // (x_a(0.4 T_S) = -S + 2 S (3 0.4^2 - 2 0.4^3)).
  const double reach = kApexReach * p.step_length;
  p.apex_x = apex.number(
      "x", inRange(-reach, reach,
                   fmt::format("[m] (within {:g} step lengths of mid-swing: farther, the swing tip "
                               "passes below the ground before or after its apex)",
                               kApexReach)));
  p.apex_height = apex.number("height", inRange(1e-4, 2.0, "[m]"));

  const auto hip = root.map("hip");
  hip.allowOnly({"height", "bob", "start", "dsp_start", "velocity_start", "velocity_touchdown",
                 "objective", "free"});
  p.hip_height = hip.number("height", positive("[m]"));
  p.hip_bob = hip.numberOr("bob", 0.0, inRange(0.0, 0.5 * p.hip_height, "[m]"));
  p.hip_start = hip.number("start", inRange(-p.step_length, p.step_length, "[m]"));
  p.hip_dsp_start =
      hip.numberOrWord("dsp_start", "optimize", inRange(-p.step_length, 2 * p.step_length, "[m]"));
  p.hip_velocity_start =
      hip.numberOrWord("velocity_start", "optimize", inRange(-5.0, 5.0, "[m/s]"));
  p.hip_velocity_touchdown =
      hip.numberOrWord("velocity_touchdown", "optimize", inRange(-5.0, 5.0, "[m/s]"));
  if (hip.has("objective") && hip.choice("objective", {"dsp_zmp", "zmp"}) == "zmp")
    p.hip_objective = HipObjective::kZmp;
  if (hip.has("free"))
    for (const std::string& key : hip.choices("free", {"start", "height"}))
      (key == "start" ? p.hip_start_free : p.hip_height_free) = true;

  p.torso_angle = root.numberOr("torso_angle", 0.0,
                                config::angleInRange(-std::numbers::pi / 2, std::numbers::pi / 2));
  p.slope = root.numberOr(
      "slope", 0.0, config::angleInRange(-dynamics::kMaxConfigSlope, dynamics::kMaxConfigSlope));
  p.knee = root.has("knee") && root.choice("knee", {"forward", "backward"}) == "backward"
               ? KneeDirection::kBackward
               : KneeDirection::kForward;
  return p;
}

}  // namespace gaitopt::gaits
