#pragma once
/// @file hybrid_walk.hpp
/// Event-driven simulation of walking on rigid ground (DESIGN.md sec. 2, sim): single support
/// with the pinned-chain dynamics (Mu 2.7), touchdown located by root finding on the swing-tip
/// height, the impact map chosen by Mu's conditions (double impact when the trailing tip's
/// impulse pushes, P_ly > 0 (2.31a), else single impact if the trailing tip then leaves the
/// ground, ydot_b+ > 0 (2.37a)), double support with both tips pinned (2.11, KKT) until the
/// trailing normal force reaches zero or the reference's double support ends, and relabelling
/// (2.38) into the next step. A step fails on a fall (hip too low, torso beyond 60 deg), a slip
/// (friction cone left) or a tip pulling on the ground.
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "dynamics/model.hpp"
#include "sim/event_integrator.hpp"
#include "sim/push.hpp"
#include "sim/reference.hpp"
#include "sim/tracking_controller.hpp"

namespace gaitopt::sim {

/// What a walk does, whatever the ground: how many steps, and an optional push.
struct WalkPlan {
  int steps = 20;
  std::optional<Push> push;
};

struct WalkOptions : WalkPlan {
  EventIntegratorOptions integrator;
};

/// The robot at some instant of the walk, for logs and pictures.
struct WalkSample {
  double t = 0;  ///< since the start of the walk [s]
  int step = 0;
  gaits::Phase phase = gaits::Phase::kSsp;
  VecD theta, dtheta, theta_ref, tau, tau_ref;
  Vec2d force_stance = Vec2d::Zero(), force_swing = Vec2d::Zero();  ///< ground on robot [N]
  double stance_x = 0;  ///< world x of the stance tip B [m]
  double stance_y = 0;  ///< world y of B [m]: 0 on rigid ground, below 0 while it sinks in
};
using WalkLog = std::function<void(const WalkSample&)>;

/// One step from an SSP start to the next SSP start (after relabelling).
struct StepResult {
  bool ok = false;
  std::string failure;  ///< why the step failed ("" when ok)
  VecD theta, dtheta;   ///< the next step's start (or the state at failure)
  std::string impact;   ///< "double", "single" or "" (no touchdown)
  double ssp_duration = 0, dsp_duration = 0;
  double advance = 0;             ///< world x of the new stance tip minus the old [m]
  double max_tracking_error = 0;  ///< max |theta - theta_ref| over the step [rad]
};

/// Simulates one step of `plant` under `controller` from the SSP start (theta0, dtheta0).
StepResult simulateStep(const dynamics::Model& plant, const Controller& controller,
                        const Reference& ref, const VecD& theta0, const VecD& dtheta0,
                        const EventIntegratorOptions& options, const WalkLog& log = {},
                        double t0 = 0, int step_index = 0, double stance_x = 0,
                        const std::optional<Push>& push = {});

struct WalkResult {
  int steps_completed = 0;
  bool fell = false;
  std::string failure;
  double max_tracking_error = 0;  ///< [rad]
  std::vector<StepResult> steps;
};

/// Adds a step to the walk (its error, and the failure as "step k: ..."); false when the step
/// failed, which ends the walk. Every ground's walk keeps its record through this.
bool appendStep(WalkResult& walk, const StepResult& step);

/// Distance advanced [m] and time taken [s] over the completed steps.
struct WalkTotals {
  double distance = 0, duration = 0;
};
WalkTotals completedTotals(const WalkResult& walk);

/// Up to options.steps steps from the reference's start, or (theta0, dtheta0) when given.
WalkResult simulateWalk(const dynamics::Model& plant, const Controller& controller,
                        const Reference& ref, const WalkOptions& options, const WalkLog& log = {},
                        const VecD& theta0 = {}, const VecD& dtheta0 = {});

}  // namespace gaitopt::sim
