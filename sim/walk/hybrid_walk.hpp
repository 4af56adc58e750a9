#pragma once
/// @file hybrid_walk.hpp
/// Event-driven simulation of walking on rigid ground (docs/design.md#architecture). Each phase
/// runs the chain with a free base under the contact modes of contact_dynamics.hpp: single support
/// with B sticking (Mu 2.7), touchdown located by root finding on the swing-tip height, the
/// impact map with Coulomb friction (dynamics/impact/frictional_impact.hpp; with every tip sticking
/// it is Mu's 2.23-2.37), chosen by Mu's conditions (double impact when the trailing tip's impulse
/// pushes, P_ly > 0 (2.31a), else single impact if the trailing tip then leaves the ground,
/// ydot_b+ > 0 (2.37a)), double support with both tips on the ground (2.11) until the trailing
/// normal force reaches zero or the reference's double support ends, and relabelling (2.38)
/// into the next step.
///
/// Slip is measured, not fatal (Hurmuzlu, Genot, Brogliato 2001, sec. 3.3.1): a tip left sliding
/// by a sliding impact, or whose sticking force leaves the friction cone, slides with the force
/// -mu N sgn(v_t) (held on the ground in the normal direction) until its tangential velocity
/// crosses zero, when it sticks again where it has slid to (or slides on if the cone is still
/// left). The dynamics of the chain do not depend on where its base is, so a slid B or E only
/// moves the step's origin: the step advance is measured from B's start to E's final world
/// position. A tip still sliding when the step ends carries its velocity into the next step
/// (StepResult::stance_velocity). Failures follow contact_rules.hpp, the same on every ground.
#include <functional>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "dynamics/model.hpp"
#include "sim/contact/contact_rules.hpp"
#include "sim/contact/ground_model.hpp"
#include "sim/controllers/reference.hpp"
#include "sim/controllers/tracking_controller.hpp"
#include "sim/walk/event_integrator.hpp"
#include "sim/walk/push.hpp"

namespace gaitopt::sim {

/// What a walk does, whatever the ground: how many steps, and an optional push.
struct WalkPlan {
  int steps = 20;
  std::optional<Push> push;
  ContactRules rules;
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
  double advance = 0;  ///< world x of the new stance tip minus the old (where it landed) [m]
  double max_tracking_error = 0;  ///< max |theta - theta_ref| over the step [rad]
  /// Largest distance a tip on the ground moved along it from where it was set down [m].
  double slip = 0;
  /// Least margin of the CoP the controller asked of the stance foot in single support, inside
  /// [-heel, toe] (negative: outside, so saturated or a foot rotation; contact_rules.hpp
  /// loadedCopMargin); +inf without an actuated ankle [m].
  double min_cop_margin = std::numeric_limits<double>::infinity();
  double cop_saturated_time = 0;  ///< time the ankle torque was saturated [s]
  double max_friction_ratio = 0;  ///< largest loadedFrictionRatio of a tip (contact_rules.hpp)
  /// Largest turn of a loaded foot from flat [rad]: DART's feet are bodies; the other grounds'
  /// feet are CoP bounds and never turn (their foot rotation is min_cop_margin < 0).
  double max_foot_tilt = 0;
  double stance_velocity = 0;  ///< the new stance tip's sliding velocity at the next start [m/s]
  /// Rigid ground: deepest the swing tip went below the ground in single support, wherever it
  /// was (ahead of B, where touchdown ends the phase, or behind it, where the rigid ground has
  /// no contact and the tip passes through), over the integrator's accepted and event-located
  /// states; 0 when it never went below [m]. NaN (not measured) on the compliant grounds and
  /// DART, whose ground pushes any tip below it back: there a tip in the ground is a contact.
  double max_tip_penetration = std::numeric_limits<double>::quiet_NaN();
};

/// Simulates one step of `plant` under `controller` from the SSP start (theta0, dtheta0), B at
/// world x = stance_x sliding at stance_velocity.
StepResult simulateStep(const dynamics::Model& plant, const Controller& controller,
                        const Reference& ref, const VecD& theta0, const VecD& dtheta0,
                        const EventIntegratorOptions& options, const WalkLog& log = {},
                        double t0 = 0, int step_index = 0, double stance_x = 0,
                        const std::optional<Push>& push = {}, const ContactRules& rules = {},
                        double stance_velocity = 0);

/// The closed loop inside single support at step clock `clock`, the stance tip sticking where it
/// was set down: link angles and rates, and the controller's memory (controller.hpp), which is
/// not zero there. A Poincare section inside single support (poincare.hpp) takes this state.
struct SspState {
  double clock = 0;  ///< [s]
  VecD theta, dtheta;
  Eigen::VectorXd memory;  ///< size controller.memorySize(kSsp)
};

/// The step from `s` on (touchdown, impact, DSP, relabelling), as simulateStep from the
/// step's start; step index 0 (for `push`). ssp_duration counts from the step's start.
/// @throws std::invalid_argument when s.clock is before the reference's fadeTime(): the
///         reference there still depends on where the step started.
StepResult simulateStepFrom(const dynamics::Model& plant, const Controller& controller,
                            const Reference& ref, const SspState& s,
                            const EventIntegratorOptions& options, const ContactRules& rules = {},
                            const std::optional<Push>& push = {});

/// The single support from the step's start (theta0, dtheta0) up to step clock `clock`.
struct SspRun {
  bool ok = false;
  std::string failure;  ///< a failure, a touchdown before `clock`, or B sliding at `clock`
  SspState state;
};
SspRun simulateSingleSupportTo(const dynamics::Model& plant, const Controller& controller,
                               const Reference& ref, const VecD& theta0, const VecD& dtheta0,
                               double clock, const EventIntegratorOptions& options,
                               const ContactRules& rules = {}, double stance_velocity = 0);

struct WalkResult {
  int steps_completed = 0;
  bool fell = false;
  std::string failure;
  double max_tracking_error = 0;  ///< [rad]
  double max_slip = 0;            ///< largest StepResult::slip [m]
  double min_cop_margin = std::numeric_limits<double>::infinity();  ///< least of the steps' [m]
  double cop_saturated_time = 0;                                    ///< [s]
  double max_friction_ratio = 0;  ///< largest StepResult::max_friction_ratio
  double max_foot_tilt = 0;       ///< largest StepResult::max_foot_tilt [rad]
  /// Largest StepResult::max_tip_penetration [m]; NaN when no step measured it (not rigid).
  double max_tip_penetration = std::numeric_limits<double>::quiet_NaN();
  std::vector<StepResult> steps;
};

/// A touchdown this short of the planned step is the swing tip striking the ground at mid-swing,
/// not a step (a scuff each time step, a robot standing with its legs together, was counted as
/// 20 steps walked); pushes and model errors shorten steps by far less.
inline constexpr double kMinStepFraction = 0.25;

/// Adds a step to the walk (its error, and the failure as "step k: ..."); false when the step
/// failed, which ends the walk, also when it advanced less than kMinStepFraction of
/// `planned_step` [m] (a scuff, also when the rigid ground's impact there failed: "double" or
/// "single" with `advance` where the tip landed). Every ground's walk keeps its record through
/// this.
bool appendStep(WalkResult& walk, StepResult step, double planned_step);

/// Distance advanced [m] and time taken [s] over the completed steps.
struct WalkTotals {
  double distance = 0, duration = 0;
};
WalkTotals completedTotals(const WalkResult& walk);

/// 1-based index of the step whose max_tip_penetration is walk.max_tip_penetration, 0 when none
/// measured it.
int deepestPenetrationStep(const WalkResult& walk);

/// Up to options.steps steps from the reference's start, or (theta0, dtheta0) when given.
WalkResult simulateWalk(const dynamics::Model& plant, const Controller& controller,
                        const Reference& ref, const WalkOptions& options, const WalkLog& log = {},
                        const VecD& theta0 = {}, const VecD& dtheta0 = {});

/// simulateWalk on `ground`'s event integrator: the rigid ground's walk (ground_registry.cpp).
WalkResult walkRigid(const dynamics::Model& plant, const Controller& controller,
                     const Reference& ref, const RigidGround& ground, const WalkPlan& plan,
                     const WalkLog& log = {}, const VecD& theta0 = {}, const VecD& dtheta0 = {});

}  // namespace gaitopt::sim
