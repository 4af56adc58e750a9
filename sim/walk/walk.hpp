#pragma once
/// @file walk.hpp
/// One entry point for a closed-loop walk on any ground of ground_model.hpp: rigid
/// (hybrid_walk.hpp), compliant (compliant_walk.hpp), time-stepping LCP (lcp_walk.hpp), DART
/// (dart_walk.hpp) or another of ground_registry.hpp. All fill the same WalkResult and call the
/// same WalkLog.
#include "sim/contact/ground_model.hpp"
#include "sim/walk/hybrid_walk.hpp"

namespace gaitopt::sim {

/// Up to plan.steps steps of `plant` under `controller` on `ground`, from the reference's start or
/// (theta0, dtheta0) when given.
/// @throws std::invalid_argument when the ground's parameters are out of range or no registered
/// ground has its settings.
WalkResult walk(const dynamics::Model& plant, const Controller& controller, const Reference& ref,
                const GroundModel& ground, const WalkPlan& plan, const WalkLog& log = {},
                const VecD& theta0 = {}, const VecD& dtheta0 = {});

}  // namespace gaitopt::sim
