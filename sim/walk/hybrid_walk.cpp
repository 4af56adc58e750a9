#include "sim/walk/hybrid_walk.hpp"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace gaitopt::sim {

bool appendStep(WalkResult& walk, StepResult step, double planned_step) {
  const bool landed = step.ok || step.impact == "double" || step.impact == "single";
  if (landed && step.advance < kMinStepFraction * planned_step) {
    step.ok = false;
    step.failure = fmt::format(
        "the swing tip struck the ground {:.3g} m ahead of the stance tip, {:.0f} % of the "
        "planned {:.3g} m step: a scuff at mid-swing, not a step",
        step.advance, 100 * step.advance / planned_step, planned_step);
  }
  walk.max_tracking_error = std::max(walk.max_tracking_error, step.max_tracking_error);
  walk.max_slip = std::max(walk.max_slip, step.slip);
  walk.min_cop_margin = std::min(walk.min_cop_margin, step.min_cop_margin);
  walk.cop_saturated_time += step.cop_saturated_time;
  walk.max_friction_ratio = std::max(walk.max_friction_ratio, step.max_friction_ratio);
  walk.max_foot_tilt = std::max(walk.max_foot_tilt, step.max_foot_tilt);
  // fmax skips a NaN (a ground that does not measure it) on either side.
  walk.max_tip_penetration = std::fmax(walk.max_tip_penetration, step.max_tip_penetration);
  walk.steps.push_back(step);
  if (!step.ok) {
    walk.fell = true;
    walk.failure = fmt::format("step {}: {}", walk.steps.size(), step.failure);
    return false;
  }
  ++walk.steps_completed;
  return true;
}

WalkTotals completedTotals(const WalkResult& walk) {
  WalkTotals totals;
  for (int k = 0; k < walk.steps_completed; ++k) {
    const StepResult& s = walk.steps[static_cast<std::size_t>(k)];
    totals.distance += s.advance;
    totals.duration += s.ssp_duration + s.dsp_duration;
  }
  return totals;
}

int deepestPenetrationStep(const WalkResult& walk) {
  for (std::size_t k = 0; k < walk.steps.size(); ++k)
    if (walk.steps[k].max_tip_penetration == walk.max_tip_penetration)
      return static_cast<int>(k) + 1;
  return 0;
}

WalkResult simulateWalk(const dynamics::Model& plant, const Controller& controller,
                        const Reference& ref, const WalkOptions& options, const WalkLog& log,
                        const VecD& theta0, const VecD& dtheta0) {
  WalkResult w;
  VecD theta = theta0.size() ? theta0 : VecD(ref.start().theta);
  VecD dtheta = dtheta0.size() ? dtheta0 : VecD(ref.start().dtheta);
  double t = 0, stance_x = 0, stance_velocity = 0;
  for (int k = 0; k < options.steps; ++k) {
    const StepResult s =
        simulateStep(plant, controller, ref, theta, dtheta, options.integrator, log, t, k, stance_x,
                     options.push, options.rules, stance_velocity);
    if (!appendStep(w, s, ref.stepLength())) break;
    t += s.ssp_duration + s.dsp_duration;
    stance_x += s.advance;
    stance_velocity = s.stance_velocity;
    theta = s.theta;
    dtheta = s.dtheta;
  }
  return w;
}

WalkResult walkRigid(const dynamics::Model& plant, const Controller& controller,
                     const Reference& ref, const RigidGround& ground, const WalkPlan& plan,
                     const WalkLog& log, const VecD& theta0, const VecD& dtheta0) {
  return simulateWalk(plant, controller, ref, WalkOptions{plan, ground.integrator}, log, theta0,
                      dtheta0);
}

}  // namespace gaitopt::sim
