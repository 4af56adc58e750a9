#include <numbers>

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
  p.apex_x = apex.number("x", inRange(-0.999 * p.step_length, 0.999 * p.step_length,
                                      "[m] (strictly between the start and end of the swing)"));
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
