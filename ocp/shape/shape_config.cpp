#include "ocp/shape/shape_config.hpp"

namespace gaitopt::ocp {
namespace {

using config::YamlReader;

constexpr int kMaxSteps = 4;
constexpr int kMaxVariants = 8;

int readSteps(const YamlReader& root) {
  return static_cast<int>(root.numberOr("steps", 1, config::wholeInRange(1, kMaxSteps, "(steps)")));
}

VariantConfig readVariant(const YamlReader& r) {
  r.allowOnly({"mass_scale", "length_scale", "controller_case"});
  VariantConfig v;
  v.mass_scale = r.numberOr("mass_scale", 1, config::inRange(0.5, 2.0, "(times the nominal mass)"));
  v.length_scale =
      r.numberOr("length_scale", 1, config::inRange(0.8, 1.25, "(times the nominal lengths)"));
  v.controller_case = static_cast<int>(
      r.numberOr("controller_case", 1, config::wholeInRange(1, 3, "(Mu's case 1, 2 or 3)")));
  if (v.mass_scale == 1 && v.length_scale == 1 && v.controller_case == 1)
    r.fail("mass_scale",
           "a variant differs from the nominal: give mass_scale, length_scale or controller_case");
  return v;
}

FeedbackGains readFeedback(const YamlReader& r) {
  r.allowOnly({"law", "kp", "kd", "dsp_kp", "dsp_kd"});
  FeedbackGains g;
  const std::string law = r.has("law") ? r.choice("law", {"joint_pd", "computed_torque"}) : "";
  if (law != "computed_torque") {
    if (r.has("dsp_kp") || r.has("dsp_kd"))
      r.fail("dsp_kp", "only meaningful with law: computed_torque");
    g.kp = r.number("kp", config::inRange(0, 1e5, "[N m / rad]"));
    g.kd = r.number("kd", config::inRange(0, 1e4, "[N m s / rad]"));
    return g;
  }
  g.law = FeedbackGains::Law::kComputedTorque;
  g.kp = r.number("kp", config::inRange(0, 1e6, "[1/s^2]"));
  g.kd = r.number("kd", config::inRange(0, 1e4, "[1/s]"));
  g.dsp_kp = r.number("dsp_kp", config::inRange(0, 1e5, "[N m / rad]"));
  g.dsp_kd = r.number("dsp_kd", config::inRange(0, 1e4, "[N m s / rad]"));
  return g;
}

}  // namespace

const std::vector<std::string>& shapeKeys() {
  static const std::vector<std::string> keys = {
      "steps",          "variants",       "variant_feedback", "variant_end_tolerance",
      "variant_spread", "variant_contact"};
  return keys;
}

ShapeConfig readShapeConfig(const YamlReader& root) {
  ShapeConfig s;
  s.steps = readSteps(root);
  if (!root.has("variants")) {
    for (const char* key :
         {"variant_feedback", "variant_end_tolerance", "variant_spread", "variant_contact"})
      if (root.has(key)) root.fail(key, "only meaningful with `variants`");
    return s;
  }
  for (const auto& item : root.list("variants")) {
    const VariantConfig v = readVariant(item);
    // A copy given twice duplicates its rows: the same plant weighed double, at twice the size.
    for (const VariantConfig& before : s.variants)
      if (before.mass_scale == v.mass_scale && before.length_scale == v.length_scale &&
          before.controller_case == v.controller_case)
        item.fail("mass_scale", "the same variant is given twice");
    s.variants.push_back(v);
  }
  if (s.variants.empty() || static_cast<int>(s.variants.size()) > kMaxVariants)
    root.fail("variants", "expected 1 to 8 variants besides the nominal");
  // Without the law a variant's torques are free and the ensemble says nothing.
  s.feedback = readFeedback(root.map("variant_feedback"));
  s.end_tolerance =
      root.number("variant_end_tolerance", config::inRange(1e-6, 10, "(state distance)"));
  s.spread = root.numberOr("variant_spread", 0.0, config::inRange(0, 1e6, "(weight)"));
  s.contact = root.booleanOr("variant_contact", true);
  return s;
}

}  // namespace gaitopt::ocp
