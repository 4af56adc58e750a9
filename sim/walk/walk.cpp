#include "sim/walk/walk.hpp"

#include "sim/walk/ground_registry.hpp"

namespace gaitopt::sim {

WalkResult walk(const dynamics::Model& plant, const Controller& controller, const Reference& ref,
                const GroundModel& ground, const WalkPlan& plan, const WalkLog& log,
                const VecD& theta0, const VecD& dtheta0) {
  return groundEntryOf(ground).walk(ground, {plant, controller, ref, plan, log, theta0, dtheta0});
}

}  // namespace gaitopt::sim
