#include "sim/hybrid_walk.hpp"

#include <cmath>
#include <numbers>

#include <fmt/format.h>

#include "dynamics/dsp_dynamics.hpp"
#include "dynamics/ground.hpp"
#include "dynamics/impact.hpp"
#include "dynamics/kinematics.hpp"
#include "dynamics/relabel.hpp"
#include "dynamics/ssp_dynamics.hpp"

namespace gaitopt::sim {
namespace {

using gaits::Phase;
constexpr double kMaxTorsoLean = std::numbers::pi / 3;  // 60 deg from upright: a fall
// Contact is detected this close to the ground: a gait that sets its swing tip down with zero
// velocity (Mu ch. 3) only touches y = 0 tangentially, which a sign change would miss [m].
constexpr double kContactDistance = 1e-6;

/// The phase's integrated state: the plant's (theta, dtheta) and the controller's memory.
Eigen::VectorXd join(const VecD& theta, const VecD& dtheta, const Eigen::VectorXd& memory) {
  Eigen::VectorXd x(theta.size() + dtheta.size() + memory.size());
  x << theta, dtheta, memory;
  return x;
}

/// The closed loop in one phase: controller torques, plant accelerations and contact forces.
/// The reference starts from where the robot is (`start`, reference.hpp).
struct ClosedLoop {
  ClosedLoop(const dynamics::Model& plant_, const Controller& controller_, const Reference& ref_,
             Phase phase_, PhaseStart start_, const std::optional<Push>& push_ = {}, int step_ = 0)
      : plant(plant_),
        controller(controller_),
        ref(ref_),
        phase(phase_),
        start(std::move(start_)),
        push(push_),
        step(step_) {}

  const dynamics::Model& plant;
  const Controller& controller;
  const Reference& ref;
  Phase phase;
  PhaseStart start;
  std::optional<Push> push;  ///< acts in single support only
  int step;                  ///< 0-based, for the push

  /// The integrated state at the phase start: the controller's memory starts at zero.
  Eigen::VectorXd initial(const VecD& theta, const VecD& dtheta) const {
    return join(theta, dtheta, Eigen::VectorXd::Zero(controller.memorySize(phase)));
  }

  struct State {
    VecD theta, dtheta, ddtheta, tau;
    Vec2d force_stance, force_swing = Vec2d::Zero();
    gaits::Knot ref;
    Eigen::VectorXd memory, memory_rate;
  };

  /// The closed loop at (t, x). The last evaluation is kept: the event functions and the
  /// observer ask for the state an RK4 step ended at, and the next step's first stage starts
  /// there, so 4 evaluations per step do instead of 6.
  const State& at(double t, const Eigen::VectorXd& x) const {
    if (cached_ && cached_t_ == t && cached_x_ == x) return cached_state_;
    cached_state_ = evaluate(t, x);
    cached_t_ = t;
    cached_x_ = x;
    cached_ = true;
    return cached_state_;
  }

  Eigen::VectorXd rhs(double t, const Eigen::VectorXd& x) const {
    const State& s = at(t, x);
    return join(s.dtheta, s.ddtheta, s.memory_rate);
  }

  State evaluate(double t, const Eigen::VectorXd& x) const {
    const int n = plant.nLinks();
    State s{x.head(n),
            x.segment(n, n),
            {},
            {},
            {},
            Vec2d::Zero(),
            ref.at(phase, t, start),
            x.tail(x.size() - 2 * n),
            {}};
    s.tau = controller.torque(phase, s.theta, s.dtheta, s.ref, s.memory);
    s.memory_rate = controller.memoryRate(phase, s.theta, s.dtheta, s.ref, s.memory);
    Vec2d pushed = Vec2d::Zero();  // the push's force on the hip
    if (phase == Phase::kSsp) {
      s.ddtheta = dynamics::sspForwardDynamics(plant, s.theta, s.dtheta, s.tau);
      pushed = pushForce(push, step, t, ref.touchdownTime());
      if (!pushed.isZero())  // D thetaddot = ... + J_H^T F (Mu 2.7 with an external force)
        s.ddtheta +=
            dynamics::massMatrix<double>(plant, s.theta)
                .ldlt()
                .solve(dynamics::pointJacobian<double>(plant.hipWeights(), s.theta).transpose() *
                       pushed);
    } else {
      const auto dsp = dynamics::dspForwardDynamics(plant, s.theta, s.dtheta, s.tau);
      s.ddtheta = dsp.ddtheta;
      s.force_swing = dsp.force_swing;
    }
    // The ground carries what the push does not: F_B = m (a_com + g) - F_E - F_push.
    s.force_stance = dynamics::stanceForce<double>(plant, s.theta, s.dtheta, s.ddtheta,
                                                   Vec2d(s.force_swing + pushed));
    return s;
  }

  // The cache of at(); the phase's closed loop is local to one step, never shared by threads.
  mutable bool cached_ = false;
  mutable double cached_t_ = 0;
  mutable Eigen::VectorXd cached_x_;
  mutable State cached_state_;
};

double legLength(const dynamics::Model& m) {
  double length = 0;
  for (int i = 0; i < m.legLinks(); ++i) length += m.link(i).length;
  return length;
}

/// Failure margins shared by both phases (> 0 while walking): hip height above half a leg,
/// torso lean, normal force and friction at the stance tip.
Eigen::VectorXd failureMargins(const dynamics::Model& m, const ClosedLoop::State& s) {
  const double hip_y = dynamics::hip<double>(m, s.theta)(1);
  const double lean = m.torso() ? kMaxTorsoLean - std::abs(s.theta(*m.torso())) : 1.0;
  const Vec2d f = s.force_stance;
  Eigen::VectorXd g(4);
  g << hip_y - 0.5 * legLength(m), lean, f(1), m.friction() * f(1) - std::abs(f(0));
  return g;
}
const char* const kFailures[] = {"fall: hip below half the leg length", "fall: torso beyond 60 deg",
                                 "stance tip lifts off the ground", "stance tip slips"};

struct PhaseOutcome {
  EventIntegration end;
  std::string failure;
};

/// Integrates one phase; events [0, first_failure) end it normally.
PhaseOutcome runPhase(const ClosedLoop& loop, const Events& events, int first_failure,
                      const std::vector<std::string>& names, double t0, const Eigen::VectorXd& x0,
                      double t_end, const EventIntegratorOptions& o, const StepObserver& observe) {
  const Eigen::VectorXd g0 = events(t0, x0);
  for (int i = first_failure; i < g0.size(); ++i)
    if (g0(i) <= 0) return {{t0, x0, i}, names[static_cast<size_t>(i)]};
  PhaseOutcome out{
      integrateToEvent([&](double t, const Eigen::VectorXd& x) { return loop.rhs(t, x); }, events,
                       t0, x0, t_end, o, observe),
      ""};
  if (out.end.event >= first_failure) out.failure = names[static_cast<size_t>(out.end.event)];
  return out;
}

/// The SSP from the step start to touchdown, integrated in pieces between the push pulse's
/// switching times, so no RK4 step straddles a jump of the force.
PhaseOutcome runSingleSupport(const ClosedLoop& ssp, const Events& events,
                              const std::vector<std::string>& names, const Eigen::VectorXd& x0,
                              const EventIntegratorOptions& o, const StepObserver& observe) {
  const double t_end = 3 * ssp.ref.touchdownTime();
  std::vector<double> ends;
  if (ssp.push && ssp.push->step == ssp.step + 1) {
    const double start = pushStart(*ssp.push, ssp.ref.touchdownTime());
    for (double switching : {start, start + ssp.push->duration})
      if (switching > 0 && switching < t_end) ends.push_back(switching);
  }
  ends.push_back(t_end);
  double t = 0;
  Eigen::VectorXd x = x0;
  PhaseOutcome out;
  for (double end : ends) {
    out = runPhase(ssp, events, 1, names, t, x, end, o, observe);
    if (!out.failure.empty() || out.end.event >= 0) return out;
    t = out.end.t;
    x = out.end.x;
  }
  return out;
}

}  // namespace

namespace {

/// The step's bookkeeping while it runs: tracking error and the log.
struct StepRecorder {
  StepResult& result;
  const WalkLog& log;
  int step;
  double stance_x;

  StepObserver observer(const ClosedLoop& loop, double global_minus_clock) {
    return [this, &loop, global_minus_clock](double t, const Eigen::VectorXd& x) {
      const ClosedLoop::State s = loop.at(t, x);
      const double error = (s.theta - VecD(s.ref.theta)).cwiseAbs().maxCoeff();
      result.max_tracking_error = std::max(result.max_tracking_error, error);
      if (log)
        log({t + global_minus_clock, step, loop.phase, s.theta, s.dtheta, s.ref.theta, s.tau,
             s.ref.tau, s.force_stance, s.force_swing, stance_x});
    };
  }
};

/// A single impact that lifts the trailing tip slower than this is treated as a double one:
/// the rigid impulse analysis ignores the finite ground force that still loads the trailing
/// tip, which then decides lift-off in the double support [m/s].
constexpr double kGentleLiftoff = 0.01;

/// The impact map by Mu's conditions; "" when neither is admissible or the impulse slips.
std::string chooseImpact(const dynamics::Model& plant, const VecD& theta, VecD& dtheta,
                         std::string& failure) {
  const auto both = dynamics::doubleImpact(plant, theta, dtheta);
  const auto single = dynamics::singleImpact(plant, theta, dtheta);
  const bool gentle = single.trailing_velocity(1) < kGentleLiftoff;
  const bool use_double = both.unilateral_ok || gentle;
  const auto& chosen = use_double ? both : single;
  if (!chosen.unilateral_ok && !gentle) {
    failure = "no admissible impact (neither 2.31a nor 2.37a holds)";
    return "";
  }
  // A vanishing impulse (a gentle touchdown) cannot slip whatever its direction.
  const double impulse = std::max(chosen.impulse_leading.norm(), chosen.impulse_trailing.norm());
  if (!chosen.friction_ok && impulse > plant.totalMass() * plant.gravity() * kNegligibleImpulseTime)
    failure = "impact impulse outside the friction cone";
  dtheta = chosen.dtheta_plus;
  return use_double ? "double" : "single";
}

}  // namespace

StepResult simulateStep(const dynamics::Model& plant, const Controller& controller,
                        const Reference& ref, const VecD& theta0, const VecD& dtheta0,
                        const EventIntegratorOptions& o, const WalkLog& log, double t0,
                        int step_index, double stance_x, const std::optional<Push>& push) {
  StepResult r;
  StepRecorder recorder{r, log, step_index, stance_x};
  const ClosedLoop ssp{
      plant, controller, ref, Phase::kSsp, ref.startFrom(Phase::kSsp, 0, theta0, dtheta0),
      push,  step_index};
  const auto ssp_events = [&](double t, const Eigen::VectorXd& x) {
    const auto s = ssp.at(t, x);
    const Vec2d tip = dynamics::swingTip<double>(plant, s.theta);
    Eigen::VectorXd g(5);
    g << (tip(0) > 0 ? tip(1) - kContactDistance : 1.0), failureMargins(plant, s);  // ahead of B
    return g;
  };
  const std::vector<std::string> ssp_names{"touchdown", kFailures[0], kFailures[1], kFailures[2],
                                           kFailures[3]};
  PhaseOutcome phase = runSingleSupport(ssp, ssp_events, ssp_names, ssp.initial(theta0, dtheta0), o,
                                        recorder.observer(ssp, t0));
  const int n = plant.nLinks();
  VecD theta = phase.end.x.head(n), dtheta = phase.end.x.segment(n, n);
  r.ssp_duration = phase.end.t;
  if (phase.failure.empty() && phase.end.event < 0)
    phase.failure = "no touchdown within 3 times the planned single support";
  if (phase.failure.empty()) r.impact = chooseImpact(plant, theta, dtheta, phase.failure);
  if (phase.failure.empty() && r.impact == "double" && ref.hasDsp()) {
    const double start = ref.dspClockAt(theta);
    const ClosedLoop dsp{plant, controller, ref, Phase::kDsp,
                         ref.startFrom(Phase::kDsp, start, theta, dtheta)};
    const auto dsp_events = [&](double t, const Eigen::VectorXd& x) {
      const auto s = dsp.at(t, x);
      const Vec2d fe = s.force_swing;
      Eigen::VectorXd g(6);
      g << s.force_stance(1), failureMargins(plant, s).head(2), fe(1),
          plant.friction() * s.force_stance(1) - std::abs(s.force_stance(0)),
          plant.friction() * fe(1) - std::abs(fe(0));
      return g;
    };
    const std::vector<std::string> dsp_names{
        "trailing tip unloads", kFailures[0],
        kFailures[1],           "leading tip lifts off the ground",
        "trailing tip slips",   "leading tip slips"};
    phase = runPhase(dsp, dsp_events, 1, dsp_names, start, dsp.initial(theta, dtheta),
                     ref.endTime(), o, recorder.observer(dsp, t0 + r.ssp_duration - start));
    theta = phase.end.x.head(n);
    dtheta = phase.end.x.segment(n, n);
    r.dsp_duration = phase.end.t - start;
  }
  r.failure = phase.failure;
  r.ok = r.failure.empty();
  r.theta = theta;
  r.dtheta = dtheta;
  if (!r.ok) return r;
  r.advance = dynamics::swingTip<double>(plant, theta)(0);  // lift-off: E becomes the stance
  r.theta = dynamics::relabelAngles<double>(plant, theta);
  r.dtheta = dynamics::relabelRates<double>(dtheta);
  return r;
}

bool appendStep(WalkResult& walk, const StepResult& step) {
  walk.max_tracking_error = std::max(walk.max_tracking_error, step.max_tracking_error);
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

WalkResult simulateWalk(const dynamics::Model& plant, const Controller& controller,
                        const Reference& ref, const WalkOptions& options, const WalkLog& log,
                        const VecD& theta0, const VecD& dtheta0) {
  WalkResult w;
  VecD theta = theta0.size() ? theta0 : VecD(ref.start().theta);
  VecD dtheta = dtheta0.size() ? dtheta0 : VecD(ref.start().dtheta);
  double t = 0, stance_x = 0;
  for (int k = 0; k < options.steps; ++k) {
    const StepResult s = simulateStep(plant, controller, ref, theta, dtheta, options.integrator,
                                      log, t, k, stance_x, options.push);
    if (!appendStep(w, s)) break;
    t += s.ssp_duration + s.dsp_duration;
    stance_x += s.advance;
    theta = s.theta;
    dtheta = s.dtheta;
  }
  return w;
}

}  // namespace gaitopt::sim
