#include "sim/walk/free_base_walk.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "dynamics/energy.hpp"
#include "dynamics/floating_base_dynamics.hpp"
#include "dynamics/impact/relabel.hpp"
#include "dynamics/kinematics.hpp"

namespace gaitopt::sim {
namespace {

using gaits::Phase;

VecD anglesOf(const dynamics::Model& plant, const Eigen::VectorXd& q) {
  return q.tail(plant.nLinks());
}

double legLength(const dynamics::Model& m) {
  double length = 0;
  for (int i = 0; i < m.legLinks(); ++i) length += m.link(i).length;
  return length;
}

/// The step in progress: phase, clocks and the time each stance tip has been unloaded.
struct StepRun {
  FreeBaseState s;
  Phase phase = Phase::kSsp;
  double clock = 0;    ///< the controller's step clock (jumps at touchdown) [s]
  double elapsed = 0;  ///< time since the step started [s]
  double b_unloaded = 0, e_unloaded = 0;
  double b_x0 = 0;  ///< world x of the stance tip at the step start [m]
  double e_x0 = 0;  ///< world x of the swing tip at touchdown [m]
  TipForces force;
  double stance_foot_tilt = 0;  ///< ContactStep's [rad]
  Eigen::VectorXd memory;       ///< the controller's, from phaseStartMemory at each phase start
  PhaseStart start;             ///< the robot's departure faded out of the reference (SSP only)
};

/// The stance ankle's torque and what the foot can carry (contact_rules.hpp), at B's normal force
/// of the last time step (the contact laws give the force only with the step).
struct AnkleLimit {
  double lower = 0, upper = 0;  ///< tau0 in [-toe F_y, heel F_y] [N m]
  bool active = false;          ///< an actuated ankle on a loaded foot
};

/// Everything a step needs that does not change during the walk.
struct Walker {
  const dynamics::Model& plant;
  const Controller& controller;
  const Reference& ref;
  const FreeBaseGround& ground;
  const ContactRules& rules;
  const WalkLog& log;

  AnkleLimit ankleLimit(const StepRun& run) const {
    const auto range = dynamics::ankleTorqueRange(run.force.b(1), plant.foot());
    return {range.lower, range.upper, plant.joints().front().actuated};
  }

  /// Saturates in the DSP always (the trailing foot rolls onto its toe), in the SSP when the
  /// rules say so.
  bool saturates(Phase phase) const {
    return rules.cop_limit == CopLimit::kSaturate || phase == Phase::kDsp;
  }

  /// The torque the plant receives for the controller's `request`: the ankle clipped to what
  /// the foot carries when the rules saturate it (the controller clips to the torque limits).
  VecD applied(const StepRun& run, VecD request) const {
    const AnkleLimit limit = ankleLimit(run);
    if (limit.active && saturates(run.phase))
      request(0) = std::clamp(request(0), limit.lower, limit.upper);
    return request;
  }

  TorqueFeedback feedback(const StepRun& run) const {
    return [this, &run](double dt, const Eigen::VectorXd& q, const Eigen::VectorXd& v) {
      return applied(run,
                     controller.torque(run.phase, anglesOf(plant, q), anglesOf(plant, v),
                                       ref.at(run.phase, run.clock + dt, run.start), run.memory));
    };
  }

  /// The phase starts with the controller's memory for the robot's state (phaseStartMemory) and,
  /// in single support, the reference faded from the robot (reference.hpp PhaseStart), as on
  /// rigid ground. Not at touchdown: on a compliant ground the tips bounce, and fading that
  /// transient into the reference made the polynomial gait fall at step 2 on the impedance
  /// ground. The lift-off is no bounce, and there a DSP that could not match the plan's posture
  /// (E set down early, 2.6 mm short) handed the SSP 0.025 rad, 0.3 rad/s errors that Mu's SSP
  /// law (Lambda^2 = 625) turned into a stance ankle torque of +25 N m, the CoP 0.11 m behind
  /// the ankle (heel 0.05 m).
  void startPhase(StepRun& run, Phase phase, const PhaseHandover* previous) const {
    const VecD theta = anglesOf(plant, run.s.q), dtheta = anglesOf(plant, run.s.v);
    run.phase = phase;
    run.start = phase == Phase::kSsp ? ref.startFrom(phase, run.clock, theta, dtheta)
                                     : PhaseStart{run.clock, 0, {}, {}};
    run.memory = controller.phaseStartMemory(phase, theta, dtheta,
                                             ref.at(phase, run.clock, run.start), previous);
  }

  /// The phase now running, as it ends (before the clock moves on).
  PhaseHandover handover(const StepRun& run) const {
    return {run.phase, anglesOf(plant, run.s.q), anglesOf(plant, run.s.v),
            ref.at(run.phase, run.clock, run.start), run.memory};
  }

  /// The controller's memory over one time step h (explicit Euler at the step's start).
  void advanceMemory(StepRun& run, const FreeBaseState& before, double h) const {
    if (run.memory.size() == 0) return;
    const gaits::Knot k = ref.at(run.phase, run.clock, run.start);
    run.memory += h * controller.memoryRate(run.phase, anglesOf(plant, before.q),
                                            anglesOf(plant, before.v), k, run.memory);
  }

  /// "diverged: ..." for a state no contact law should reach, else "".
  std::string diverged(const FreeBaseState& s) const {
    if (!s.q.allFinite() || !s.v.allFinite() || -s.q(1) > kMaxPenetration ||
        -dynamics::floatingSwingTip(plant, s.q)(1) > kMaxPenetration)
      return "diverged: non-finite state or a tip deeper than 5 cm";
    return "";
  }

  /// Why the walk cannot go on after this time step ("" while it can).
  std::string failure(const StepRun& run) const {
    const Eigen::VectorXd& q = run.s.q;
    const VecD theta = anglesOf(plant, q);
    if (q(1) + dynamics::hip<double>(plant, theta)(1) < rules.min_hip_height * legLength(plant))
      return kFallHip;
    if (plant.torso() && std::abs(theta(*plant.torso())) > rules.max_torso_lean) return kFallTorso;
    // In the DSP an unloaded B is the trailing tip lifting off: it ends the phase instead.
    if (run.phase == Phase::kSsp && run.b_unloaded >= kLiftoffTime) return kStanceLiftoff;
    if (run.e_unloaded >= kLiftoffTime) return kLeadingLiftoff;
    if (slip(run) > rules.max_slip) return kSlip;
    return "";
  }

  /// How far the tips on the ground moved along it: B from the step start, E from touchdown [m].
  double slip(const StepRun& run) const {
    const double b = std::abs(run.s.q(0) - run.b_x0);
    if (run.phase == Phase::kSsp) return b;
    return std::max(b, std::abs(dynamics::floatingSwingTip(plant, run.s.q)(0) - run.e_x0));
  }

  /// The CoP the controller asks of the stance foot, against the foot (StepResult): the margin,
  /// the saturated time, and the foot rotation when the rules fail it.
  std::string recordAnkle(const StepRun& run, const VecD& tau, double h, StepResult& r) const {
    const AnkleLimit limit = ankleLimit(run);
    if (!limit.active) return "";
    const dynamics::Foot& foot = plant.foot();
    const double fy = run.force.b(1), tau0 = tau(0);
    if (run.phase == Phase::kSsp)
      r.min_cop_margin = std::min(
          r.min_cop_margin, loadedCopMargin(tau0, fy, foot, plant.totalMass() * plant.gravity()));
    if (dynamics::copMomentMargin(tau0, fy, foot) >= 0) return "";
    if (saturates(run.phase)) {
      r.cop_saturated_time += h;
      return "";
    }
    return kFootRotation;
  }

  /// Touchdown: E, ahead of B, is loaded or at the ground.
  bool touchedDown(const StepRun& run) const {
    const Vec2d e = dynamics::floatingSwingTip(plant, run.s.q);
    return e(0) > run.s.q(0) && (run.force.e(1) > 0 || e(1) <= 0);
  }

  void record(const StepRun& run, double t0, int index, StepResult& r) const {
    const VecD theta = anglesOf(plant, run.s.q), dtheta = anglesOf(plant, run.s.v);
    const gaits::Knot k = ref.at(run.phase, run.clock, run.start);
    r.max_tracking_error =
        std::max(r.max_tracking_error, (theta - VecD(k.theta)).cwiseAbs().maxCoeff());
    const double weight = plant.totalMass() * plant.gravity();
    r.max_friction_ratio = std::max({r.max_friction_ratio, loadedFrictionRatio(run.force.b, weight),
                                     loadedFrictionRatio(run.force.e, weight)});
    // The trailing foot rolling onto its toe in double support is walking (contact_rules.hpp).
    if (run.phase == Phase::kSsp && run.force.b(1) >= kLoadedFoot * weight)
      r.max_foot_tilt = std::max(r.max_foot_tilt, std::abs(run.stance_foot_tilt));
    const VecD request = controller.torque(run.phase, theta, dtheta, k, run.memory);
    r.failure = recordAnkle(run, request, ground.time_step, r);
    if (!log) return;
    // The torque the next time step applies at this state, as the rigid walk logs its applied
    // one: the request put the CoP up to 0.2 m behind a 5 cm heel on the impedance ground.
    log({t0 + run.elapsed, index, run.phase, theta, dtheta, k.theta, applied(run, request), k.tau,
         run.force.b, run.force.e, run.s.q(0), run.s.q(1)});
  }

  /// Touchdown of a gait with a DSP: the DSP starts at this time step's state.
  void beginDsp(StepRun& run) const {
    run.e_x0 = dynamics::floatingSwingTip(plant, run.s.q)(0);
    const PhaseHandover single_support = handover(run);
    run.clock = ref.dspClockAt(anglesOf(plant, run.s.q));
    startPhase(run, Phase::kDsp, &single_support);
  }

  /// One time step; false when the step has ended (normally or not).
  bool tick(StepRun& run, double t0, int index, StepResult& r) const {
    const ContactStep cs = ground.step(run.s, feedback(run));
    // A diverged state is neither logged nor measured: the walk ends at the last valid one.
    r.failure = cs.failure.empty() ? diverged(cs.next) : cs.failure;
    if (!r.failure.empty()) return false;
    const double h = ground.time_step;
    advanceMemory(run, run.s, h);
    run.s = cs.next;
    run.force = cs.force;
    run.stance_foot_tilt = cs.stance_foot_tilt;
    run.clock += h;
    run.elapsed += h;
    run.b_unloaded = run.force.b(1) > 0 ? 0 : run.b_unloaded + h;
    // A tip in the air does not slip: it is anchored anew where it is while unloaded.
    if (run.force.b(1) <= 0) run.b_x0 = run.s.q(0);
    if (run.phase == Phase::kDsp && run.force.e(1) <= 0)
      run.e_x0 = dynamics::floatingSwingTip(plant, run.s.q)(0);
    run.e_unloaded = run.phase == Phase::kDsp && run.force.e(1) <= 0 ? run.e_unloaded + h : 0;
    // Before the failure test: a walk ended by a slip reports the slip that ended it.
    r.slip = std::max(r.slip, slip(run));
    r.failure = failure(run);
    if (!r.failure.empty()) return false;
    // The time step that lands E ends the SSP: its state is the DSP's first, so the torque judged
    // and logged there is the DSP law's, the one the next time step applies (the SSP law's at the
    // state after the touchdown's impulse is never applied, and judged it was a spurious fall).
    const bool landed = run.phase == Phase::kSsp && touchedDown(run);
    if (landed) r.ssp_duration = run.elapsed;
    if (landed && ref.hasDsp()) beginDsp(run);
    record(run, t0, index, r);
    if (!r.failure.empty()) return false;
    if (landed) return ref.hasDsp();
    if (run.phase == Phase::kSsp) return true;
    // The trailing tip unloading ends the DSP early, as the trailing-force event of the rigid
    // walk does, but only in the DSP's second half: right after touchdown the impact can
    // unload it for a moment on a non-rigid contact (an optimum with a lightly loaded trailing
    // tip), and ending the step there would restart the clock at a posture far from its start.
    const double mid_dsp = 0.5 * (ref.touchdownTime() + ref.endTime());
    const bool over = run.clock >= ref.endTime() - h / 2 ||
                      (run.b_unloaded >= kUnloadTime && run.clock >= mid_dsp);
    if (over) r.dsp_duration = run.elapsed - r.ssp_duration;
    return !over;
  }

  StepResult step(FreeBaseState& s, double t0, int index, const std::optional<Push>& push) const {
    StepResult r;
    r.impact = ground.name;
    StepRun run;
    run.s = s;
    run.b_x0 = s.q(0);
    startPhase(run, Phase::kSsp, nullptr);
    const auto max_ticks = static_cast<long>(std::ceil(3 * ref.endTime() / ground.time_step));
    long ticks = 0;
    // The push's force at the middle of each time step, held over it.
    const auto pushed = [&] {
      const double mid = run.clock + 0.5 * ground.time_step;
      return run.phase == Phase::kSsp ? pushForce(push, index, mid, ref.touchdownTime())
                                      : Vec2d::Zero();
    };
    for (run.s.hip_force = pushed(); tick(run, t0, index, r); run.s.hip_force = pushed()) {
      if (++ticks < max_ticks) continue;
      r.failure = "the step did not end within 3 times the planned step";
      break;
    }
    r.ok = r.failure.empty();
    s = run.s;
    if (!r.ok) {
      r.theta = anglesOf(plant, s.q);
      r.dtheta = anglesOf(plant, s.v);
      if (run.phase == Phase::kSsp) r.impact.clear();
      return r;
    }
    s = relabel(s, r);
    return r;
  }

  /// Mu (2.38): E becomes the stance tip, the base moves there and the anchors swap.
  FreeBaseState relabel(const FreeBaseState& s, StepResult& r) const {
    const VecD theta = anglesOf(plant, s.q), dtheta = anglesOf(plant, s.v);
    const Vec2d e = dynamics::floatingSwingTip(plant, s.q);
    r.advance = e(0) - s.q(0);
    r.theta = dynamics::relabelAngles<double>(plant, theta);
    r.dtheta = dynamics::relabelRates<double>(dtheta);
    FreeBaseState next{s.q, s.v, s.anchor.reverse()};
    next.q << e, r.theta;
    next.v << dynamics::floatingSwingTipVelocity(plant, s.q, s.v), r.dtheta;
    return next;
  }
};

}  // namespace

Eigen::VectorXd hipForce(const dynamics::Model& plant, const Eigen::VectorXd& q,
                         const Vec2d& force) {
  if (force.isZero()) return Eigen::VectorXd::Zero(q.size());
  return dynamics::floatingJacobian(plant.hipWeights(), VecD(q.tail(plant.nLinks()))).transpose() *
         force;
}

double freeBaseEnergy(const dynamics::Model& plant, const Eigen::VectorXd& q,
                      const Eigen::VectorXd& v) {
  const int n = plant.nLinks();
  const VecD theta = q.tail(n), dtheta = v.tail(n);
  return dynamics::kineticEnergy<double>(plant, theta, dtheta, Vec2d(v.head<2>())) +
         dynamics::potentialEnergy<double>(plant, theta) -
         plant.totalMass() * plant.gravityAcceleration().dot(q.head<2>());
}

std::string divergedStep(double time_step, double created) {
  if (created <= kMaxCreatedEnergy) return "";  // false for NaN
  return fmt::format("diverged: an RK4 step of {:g} s created {:.3g} J", time_step, created);
}

FreeBaseState freeBaseStart(const dynamics::Model& plant, const VecD& theta, const VecD& dtheta,
                            double x_b, double y_b) {
  const int n = plant.nLinks();
  FreeBaseState s{Eigen::VectorXd(n + 2), Eigen::VectorXd(n + 2)};
  s.q << x_b, y_b, theta;
  s.v << 0, 0, dtheta;
  s.anchor << x_b, dynamics::floatingSwingTip(plant, s.q)(0);
  return s;
}

WalkResult walkFreeBase(const dynamics::Model& plant, const Controller& controller,
                        const Reference& ref, const FreeBaseGround& ground, const WalkPlan& plan,
                        const WalkLog& log, const VecD& theta0, const VecD& dtheta0) {
  if (!(std::isfinite(ground.time_step) && ground.time_step > 0))
    throw std::invalid_argument(fmt::format("{} ground: time step must be positive, got {}",
                                            ground.name, ground.time_step));
  const Walker walker{plant, controller, ref, ground, plan.rules, log};
  FreeBaseState s =
      freeBaseStart(plant, theta0.size() ? theta0 : VecD(ref.start().theta),
                    dtheta0.size() ? dtheta0 : VecD(ref.start().dtheta), 0, -ground.start_depth);
  WalkResult w;
  double t = 0;
  for (int k = 0; k < plan.steps; ++k) {
    const StepResult r = walker.step(s, t, k, plan.push);
    if (!appendStep(w, r, ref.stepLength())) break;
    t += r.ssp_duration + r.dsp_duration;
  }
  return w;
}

}  // namespace gaitopt::sim
