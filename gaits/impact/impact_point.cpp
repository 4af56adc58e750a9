#include "gaits/impact/impact_point.hpp"

namespace gaitopt::gaits {

ImpactPoint evaluateImpactPoint(const dynamics::Model& model, const ImpactPostureParams& params) {
  const PreImpactState state = impactPosture(model, params);
  ImpactPoint point;
  point.params = params;
  point.hip_height = impactHipHeight(model, params);
  point.type = dynamics::classifyImpact(model, state.theta, state.dtheta);
  point.lcp_type = dynamics::complementarityImpact(model, state.theta, state.dtheta, 0.0).type();
  point.double_model = dynamics::doubleImpact(model, state.theta, state.dtheta);
  point.single_model = dynamics::singleImpact(model, state.theta, state.dtheta);
  point.mu_l = impulseRatio(point.double_model.impulse_trailing);
  point.mu_r = impulseRatio(point.double_model.impulse_leading);
  point.mu_s = impulseRatio(point.single_model.impulse_leading);
  return point;
}

}  // namespace gaitopt::gaits
