#include "ocp/guess/initial_guess.hpp"

#include "gaits/polynomial/hip_plan_search.hpp"
#include "ocp/guess/straight_leg_guess.hpp"

namespace gaitopt::ocp {

gaits::Trajectory polynomialGuess(const dynamics::Model& model, const OcpConfig& config) {
  return polynomialGuess(model, gaits::loadGait(config.guess_gait_path));
}

gaits::Trajectory initialGuess(const dynamics::Model& model, const OcpConfig& config) {
  if (config.guess_gait_path.empty()) return straightLegGuess(model, config);
  return polynomialGuess(model, config);
}

gaits::Trajectory polynomialGuess(const dynamics::Model& model, const gaits::GaitParams& params) {
  const gaits::HipPlanSearch search = gaits::searchHipPlan(model, params);
  return gaits::buildTrajectory(gaits::PolynomialGait(model, params, search.plan), model, 1000);
}

}  // namespace gaitopt::ocp
