#include "sim/contact/contact_rules.hpp"

#include "dynamics/conventions.hpp"

namespace gaitopt::sim {

const char* toString(CopLimit limit) {
  return limit == CopLimit::kSaturate ? "saturate" : "fail";
}

nlohmann::ordered_json contactRulesJson(const ContactRules& rules) {
  return {{"max_slip_m", rules.max_slip},
          {"cop_limit", toString(rules.cop_limit)},
          {"restitution", rules.restitution},
          {"min_hip_height_per_leg", rules.min_hip_height},
          {"max_torso_lean_deg", rules.max_torso_lean / kDeg}};
}

}  // namespace gaitopt::sim
