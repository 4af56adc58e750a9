// One step of the rigid walk (hybrid_walk.hpp): phases of the free-base chain under stick/slide
// contact modes (contact_dynamics.hpp), switched at located events, and the frictional impact.
#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>

#include <fmt/format.h>

#include "dynamics/impact/frictional_impact.hpp"
#include "dynamics/impact/relabel.hpp"
#include "dynamics/kinematics.hpp"
#include "sim/walk/free_base_walk.hpp"
#include "sim/walk/hybrid_walk.hpp"
#include "sim/walk/rigid_contact_loop.hpp"

namespace gaitopt::sim {
namespace {

using gaits::Phase;
using State = ContactLoop::State;
// Contact is detected this close to the ground: a gait that sets its swing tip down with zero
// velocity (Mu ch. 3) only touches y = 0 tangentially, which a sign change would miss [m].
constexpr double kContactDistance = 1e-6;
/// A single impact that lifts the trailing tip slower than this is treated as a double one:
/// the rigid impulse analysis ignores the finite ground force that still loads the trailing
/// tip, which then decides lift-off in the double support [m/s].
constexpr double kGentleLiftoff = 0.01;
/// A landing tip that leaves the ground after the impact (restitution e > 0) faster than this
/// ends the walk: the phases after an impact pin it [m/s].
constexpr double kRebound = 0.01;
/// More contact-mode switches than this in one phase is a chatter the model does not resolve.
constexpr int kMaxSwitches = 64;

double legLength(const dynamics::Model& m) {
  double length = 0;
  for (int i = 0; i < m.legLinks(); ++i) length += m.link(i).length;
  return length;
}

/// A rigid-ground step's result, its tip penetration measured from 0 (StepResult).
StepResult rigidStepResult() {
  StepResult r;
  r.max_tip_penetration = 0;
  return r;
}

/// Everything a step needs that does not change during it.
struct StepContext {
  const dynamics::Model& plant;
  const Controller& controller;
  const Reference& ref;
  const EventIntegratorOptions& options;
  const ContactRules& rules;
  const std::optional<Push>& push;
  int step;
  int n() const { return plant.nLinks(); }
};

VecD anglesOf(const StepContext& c, const Eigen::VectorXd& x) {
  return x.segment(2, c.n());
}

/// The link rates in x = (q, qdot, memory) (rigid_contact_loop.hpp).
VecD ratesOf(const StepContext& c, const Eigen::VectorXd& x) {
  return x.segment(c.n() + 4, c.n());
}

/// E relative to where the step started (q = (x_b, y_b, theta)) [m].
Vec2d swingTipOf(const StepContext& c, const Eigen::VectorXd& x) {
  return x.head<2>() + dynamics::swingTip<double>(c.plant, anglesOf(c, x));
}

/// Tangential velocity of B (e = false) or E [m/s].
double tangentialVelocity(const StepContext& c, const State& s, bool e) {
  if (!e) return s.qdot(0);
  return s.qdot(0) + (dynamics::pointJacobian(c.plant.tipWeights(), s.theta) * s.dtheta)(0);
}

double tangentialAcceleration(const StepContext& c, const State& s, bool e) {
  if (!e) return s.qddot(0);
  const VecD ddtheta = s.qddot.tail(c.n());
  return s.qddot(0) +
         dynamics::pointAcceleration(c.plant.tipWeights(), s.theta, s.dtheta, ddtheta)(0);
}

/// The step's bookkeeping while it runs: tracking error, slip, CoP and the log.
struct StepRecorder {
  StepResult& result;
  const WalkLog& log;
  int step;
  double stance_x;      ///< world x of B at the step start [m]
  double e_anchor = 0;  ///< where E was set down, relative to B's start [m]
  bool e_on_ground = false;

  StepObserver observer(const StepContext& c, const ContactLoop& loop, double global_minus_clock) {
    return [this, &c, &loop, global_minus_clock, last = std::optional<double>()](
               double t, const Eigen::VectorXd& x) mutable {
      const State& s = loop.at(t, x);
      result.max_tracking_error =
          std::max(result.max_tracking_error, (s.theta - VecD(s.ref.theta)).cwiseAbs().maxCoeff());
      result.slip = std::max(result.slip, std::abs(x(0)));
      if (e_on_ground)
        result.slip = std::max(result.slip, std::abs(swingTipOf(c, x)(0) - e_anchor));
      result.min_cop_margin = std::min(result.min_cop_margin, s.cop_margin);
      const double weight = c.plant.totalMass() * c.plant.gravity();
      result.max_friction_ratio =
          std::max({result.max_friction_ratio, loadedFrictionRatio(s.force_stance, weight),
                    loadedFrictionRatio(s.force_swing, weight)});
      if (loop.phase() == Phase::kSsp)  // the swing tip, ahead of B or behind it
        result.max_tip_penetration = std::max(result.max_tip_penetration, -swingTipOf(c, x)(1));
      if (s.saturated && last) result.cop_saturated_time += t - *last;
      last = t;
      if (log)
        log({t + global_minus_clock, step, loop.phase(), s.theta, s.dtheta, s.ref.theta, s.tau,
             s.ref.tau, s.force_stance, s.force_swing, stance_x + x(0)});
    };
  }
};

/// One event of a phase: g > 0 while it has not happened.
struct EventSpec {
  enum class Kind { kFailure, kEnd, kStick, kSlide };
  Kind kind;
  std::string name;
  bool at_e = false;  ///< kStick, kSlide: the tip it concerns
  std::function<double(const State&, const Eigen::VectorXd&)> g;
};

void addTipEvents(const StepContext& c, const StepRecorder& rec, Phase phase, bool e,
                  const TipContact& tip, std::vector<EventSpec>& out) {
  if (!tip.onGround()) return;
  const double mu = c.plant.friction(), max_slip = c.rules.max_slip;
  const auto force = [e](const State& s) { return e ? s.force_swing : s.force_stance; };
  out.push_back({EventSpec::Kind::kFailure, kSlip, e,
                 [&c, &rec, e, max_slip](const State&, const Eigen::VectorXd& x) {
                   return max_slip - std::abs(e ? swingTipOf(c, x)(0) - rec.e_anchor : x(0));
                 }});
  const bool trailing = phase == Phase::kDsp && !e;
  out.push_back({trailing ? EventSpec::Kind::kEnd : EventSpec::Kind::kFailure,
                 trailing ? "trailing tip unloads" : (e ? kLeadingLiftoff : kStanceLiftoff), e,
                 [force](const State& s, const Eigen::VectorXd&) { return force(s)(1); }});
  if (tip.mode == TipContact::Mode::kStick)
    out.push_back({EventSpec::Kind::kSlide, "the friction cone is left", e,
                   [force, mu](const State& s, const Eigen::VectorXd&) {
                     return mu * force(s)(1) - std::abs(force(s)(0));
                   }});
  else
    out.push_back({EventSpec::Kind::kStick, "the slide stops", e,
                   [&c, e, s_dir = tip.direction](const State& s, const Eigen::VectorXd&) {
                     return s_dir * tangentialVelocity(c, s, e);
                   }});
}

std::vector<EventSpec> phaseEvents(const StepContext& c, const StepRecorder& rec, Phase phase,
                                   const ContactSet& contacts) {
  std::vector<EventSpec> out;
  if (phase == Phase::kSsp)
    out.push_back(
        {EventSpec::Kind::kEnd, "touchdown", false, [&c](const State&, const Eigen::VectorXd& x) {
           const Vec2d tip = swingTipOf(c, x);
           return tip(0) > x(0) ? tip(1) - kContactDistance : 1.0;  // ahead of B
         }});
  const double hip_low = c.rules.min_hip_height * legLength(c.plant);
  out.push_back({EventSpec::Kind::kFailure, kFallHip, false,
                 [&c, hip_low](const State& s, const Eigen::VectorXd& x) {
                   return x(1) + dynamics::hip<double>(c.plant, s.theta)(1) - hip_low;
                 }});
  if (c.plant.torso())
    out.push_back({EventSpec::Kind::kFailure, kFallTorso, false,
                   [&c](const State& s, const Eigen::VectorXd&) {
                     return c.rules.max_torso_lean - std::abs(s.theta(*c.plant.torso()));
                   }});
  if (phase == Phase::kSsp && c.rules.cop_limit == CopLimit::kFail)
    out.push_back({EventSpec::Kind::kFailure, kFootRotation, false,
                   [](const State& s, const Eigen::VectorXd&) { return s.cop_moment; }});
  addTipEvents(c, rec, phase, false, contacts.b, out);
  addTipEvents(c, rec, phase, true, contacts.e, out);
  return out;
}

struct PhaseEnd {
  double t = 0;
  Eigen::VectorXd x;
  ContactSet contacts;
  std::string event;    ///< the kEnd event that ended it, "" when the time ran out
  std::string failure;  ///< "" unless it failed
};

TipContact& tipOf(ContactSet& contacts, bool e) {
  return e ? contacts.e : contacts.b;
}

/// A sticking tip whose force is outside the cone starts to slide the way the net force drives
/// it (against the friction it would need); it must then accelerate that way, or neither mode is
/// consistent (a Painleve case). Returns "" or the failure.
std::string settleModes(const StepContext& c, Phase phase, const PhaseStart& start,
                        ContactSet& contacts, double t, const Eigen::VectorXd& x) {
  for (bool e : {false, true}) {
    TipContact& tip = tipOf(contacts, e);
    if (tip.mode != TipContact::Mode::kStick) continue;
    const State s =
        ContactLoop(c.plant, c.controller, c.ref, phase, start, contacts, c.rules, c.push, c.step)
            .at(t, x);
    const Vec2d f = e ? s.force_swing : s.force_stance;
    if (c.plant.friction() * f(1) >= std::abs(f(0))) continue;
    tip = TipContact::slide(f(0) > 0 ? -1.0 : 1.0);
    const State sliding =
        ContactLoop(c.plant, c.controller, c.ref, phase, start, contacts, c.rules, c.push, c.step)
            .at(t, x);
    if (tip.direction * tangentialAcceleration(c, sliding, e) <= 0)
      return "contact: neither sticking nor sliding is consistent (Painleve)";
  }
  return "";
}

/// The phase's closed loop with the work of its forces (ContactLoop::State::power) appended to
/// the state, y = (x, w), so each RK4 step is checked for the energy it created, as on the
/// compliant grounds (free_base_walk.hpp divergedStep): a step through a near-singular contact
/// left a state 4.9 km from the stance tip with 5e27 N on it, which a fall event then named.
struct WorkingLoop {
  const StepContext& c;
  const ContactLoop& loop;
  Eigen::Index size;  ///< of x

  Eigen::VectorXd start(const Eigen::VectorXd& x) const {
    Eigen::VectorXd y(size + 1);
    y << x, 0;
    return y;
  }

  Eigen::VectorXd rhs(double t, const Eigen::VectorXd& y) const {
    const Eigen::VectorXd x = y.head(size);
    Eigen::VectorXd dy(size + 1);
    dy << loop.rhs(t, x), loop.at(t, x).power;
    return dy;
  }

  double energy(const Eigen::VectorXd& y) const {
    return freeBaseEnergy(c.plant, y.head(c.n() + 2), y.segment(c.n() + 2, c.n() + 2));
  }

  std::string check(double t, const Eigen::VectorXd& y, double t_next,
                    const Eigen::VectorXd& y_next) const {
    const double work = y_next(size) - y(size);
    return divergedStep(t_next - t, energy(y_next) - energy(y) - work);
  }
};

/// integrateToEvent of the loop from (t, x) to t_end, each step checked by WorkingLoop; the
/// result's x without the work.
EventIntegration integrateChecked(const StepContext& c, const ContactLoop& loop,
                                  const Events& events, const StepObserver& observe, double t,
                                  const Eigen::VectorXd& x, double t_end) {
  const WorkingLoop working{c, loop, x.size()};
  const auto within = [&](const Eigen::VectorXd& y) { return Eigen::VectorXd(y.head(x.size())); };
  EventIntegration end = integrateToEvent(
      [&](double time, const Eigen::VectorXd& y) { return working.rhs(time, y); },
      [&](double time, const Eigen::VectorXd& y) { return events(time, within(y)); }, t,
      working.start(x), t_end, c.options,
      [&](double time, const Eigen::VectorXd& y) { observe(time, within(y)); },
      [&](double t0, const Eigen::VectorXd& y0, double t1, const Eigen::VectorXd& y1) {
        return working.check(t0, y0, t1, y1);
      });
  end.x = within(end.x);
  return end;
}

/// What a divergence with a tip sliding is: that tip's contact system (G D^-1 W,
/// contact_dynamics.hpp) passing through singular, where the accelerations it gives blow up. The
/// stance tip of the default optimum walked with its torso's CoM at 0.1 m slid for 29 ms, its
/// system's value going from -0.077 to -6e-11, before an RK4 step created 9e28 J.
std::string slidingCause(const ContactSet& contacts) {
  const bool b = contacts.b.mode == TipContact::Mode::kSlide;
  const bool e = contacts.e.mode == TipContact::Mode::kSlide;
  if (!b && !e) return "";
  return fmt::format(" while the {} (its contact system near singular: Painleve)",
                     b && e ? "stance and swing tips slide"
                     : b    ? "stance tip slides"
                            : "swing tip slides");
}

/// Integrates one phase from (t, x) through its contact-mode switches until an end event, the
/// last of `ends` (integrated piece by piece, e.g. between a push's switching times) or a failure.
PhaseEnd runPhase(const StepContext& c, StepRecorder& rec, Phase phase, const PhaseStart& start,
                  ContactSet contacts, double t, Eigen::VectorXd x, const std::vector<double>& ends,
                  double global_minus_clock) {
  const int qdot0 = c.n() + 2;  // index of xdot_b in x
  size_t piece = 0;
  for (int switches = 0; switches < kMaxSwitches;) {
    if (std::string why = settleModes(c, phase, start, contacts, t, x); !why.empty())
      return {t, x, contacts, "", why};
    const ContactLoop loop(c.plant, c.controller, c.ref, phase, start, contacts, c.rules, c.push,
                           c.step);
    const std::vector<EventSpec> specs = phaseEvents(c, rec, phase, contacts);
    const Events events = [&](double time, const Eigen::VectorXd& state) {
      const State& s = loop.at(time, state);
      Eigen::VectorXd g(static_cast<Eigen::Index>(specs.size()));
      for (size_t i = 0; i < specs.size(); ++i)
        g(static_cast<Eigen::Index>(i)) = specs[i].g(s, state);
      return g;
    };
    const Eigen::VectorXd g0 = events(t, x);
    for (size_t i = 0; i < specs.size(); ++i)
      if (specs[i].kind == EventSpec::Kind::kFailure && g0(static_cast<Eigen::Index>(i)) <= 0) {
        rec.observer(c, loop, global_minus_clock)(t, x);  // the state it failed at
        return {t, x, contacts, "", specs[i].name};
      }
    const EventIntegration end = integrateChecked(
        c, loop, events, rec.observer(c, loop, global_minus_clock), t, x, ends[piece]);
    t = end.t;
    x = end.x;
    // The last accepted state, already logged; the refused step's is garbage.
    if (!end.failure.empty()) return {t, x, contacts, "", end.failure + slidingCause(contacts)};
    if (end.event < 0) {
      if (++piece == ends.size()) return {t, x, contacts, "", ""};
      continue;
    }
    const EventSpec& e = specs[static_cast<size_t>(end.event)];
    if (e.kind == EventSpec::Kind::kFailure) return {t, x, contacts, "", e.name};
    if (e.kind == EventSpec::Kind::kEnd) return {t, x, contacts, e.name, ""};
    ++switches;
    TipContact& tip = tipOf(contacts, e.at_e);
    if (e.kind == EventSpec::Kind::kStick) {
      tip = TipContact::stick();
      if (!e.at_e) x(qdot0) = 0;  // B: the bisection leaves |v_t| below its tolerance
      continue;
    }
    const Vec2d f = e.at_e ? loop.at(t, x).force_swing : loop.at(t, x).force_stance;
    tip = TipContact::slide(f(0) > 0 ? -1.0 : 1.0);
  }
  return {t, x, contacts, "", "contact: more than 64 stick/slide switches in one phase"};
}

/// The SSP's integration pieces: up to 3 times the planned single support, split at the push
/// pulse's switching times so no RK4 step straddles a jump of the force.
std::vector<double> singleSupportEnds(const StepContext& c) {
  const double t_end = 3 * c.ref.touchdownTime();
  std::vector<double> ends;
  if (c.push && c.push->step == c.step + 1) {
    const double start = pushStart(*c.push, c.ref.touchdownTime());
    for (double switching : {start, start + c.push->duration})
      if (switching > 0 && switching < t_end) ends.push_back(switching);
  }
  ends.push_back(t_end);
  return ends;
}

struct ImpactChoice {
  std::string type;  ///< "double" or "single"
  std::string failure;
  dynamics::FrictionalImpact map;
};

/// The impact map by Mu's conditions, with Coulomb friction (frictional_impact.hpp).
ImpactChoice chooseImpact(const StepContext& c, const VecD& theta, const VecD& dtheta) {
  const double e = c.rules.restitution;
  auto both = dynamics::frictionalDoubleImpact(c.plant, theta, dtheta, e);
  auto single = dynamics::frictionalSingleImpact(c.plant, theta, dtheta, e);
  const bool gentle = single.base_velocity(1) < kGentleLiftoff;
  const bool use_double = both.unilateral_ok || gentle;
  ImpactChoice out{use_double ? "double" : "single", "", use_double ? both : single};
  if (!out.map.unilateral_ok && !gentle)
    out.failure = "no admissible impact (neither 2.31a nor 2.37a holds)";
  else if (!out.map.consistent && !gentle)
    out.failure = "no consistent frictional impact (no stick/slide mode satisfies Coulomb)";
  else if (const double rebound = out.map.leading.velocity(1); rebound > kRebound)
    // The phase after the impact pins the landing tip (the double support, or the next single
    // support from it); one that leaves the ground at e v_n would be walked while pinned.
    out.failure = fmt::format(
        "the landing tip rebounds at {:.3g} m/s (restitution {:g}): a rebound is not modelled",
        rebound, e);
  return out;
}

TipContact afterImpact(const dynamics::TipImpact& tip) {
  return tip.slides && tip.velocity(0) != 0 ? TipContact::slide(tip.velocity(0) > 0 ? 1.0 : -1.0)
                                            : TipContact::stick();
}

/// The rest of a step from single support at step clock t, state x (start: the reference's fade
/// of this step's start): touchdown, the impact, the DSP and relabelling.
StepResult finishStep(const StepContext& c, StepRecorder& rec, const PhaseStart& start,
                      const ContactSet& contacts, double t, const Eigen::VectorXd& x, double t0) {
  StepResult& r = rec.result;
  std::vector<double> ends = singleSupportEnds(c);
  ends.erase(std::remove_if(ends.begin(), ends.end() - 1, [t](double end) { return end <= t; }),
             ends.end() - 1);
  PhaseEnd phase = runPhase(c, rec, Phase::kSsp, start, contacts, t, x, ends, t0);
  r.ssp_duration = phase.t;
  if (phase.failure.empty() && phase.event.empty())
    phase.failure = "no touchdown within 3 times the planned single support";
  if (phase.failure.empty() && phase.contacts.b.mode != TipContact::Mode::kStick)
    phase.failure = "touchdown while the stance tip slides (not modelled)";
  double e_velocity = 0;  // E's tangential velocity when it becomes the stance tip
  if (phase.failure.empty()) {
    const VecD theta = anglesOf(c, phase.x), dtheta = ratesOf(c, phase.x);
    const PhaseHandover single_support{Phase::kSsp, theta, dtheta,
                                       c.ref.at(Phase::kSsp, phase.t, start),
                                       contactMemory(phase.x, c.n())};
    const ImpactChoice impact = chooseImpact(c, theta, dtheta);
    r.impact = impact.type;
    phase.failure = impact.failure;
    // Where the tip landed, kept when the impact fails: a touchdown at the stance tip (knee-less
    // legs crossing at mid-swing) leaves no consistent impact, and is a scuff
    // (hybrid_walk.hpp appendStep), not a failure of Coulomb's law.
    r.advance = swingTipOf(c, phase.x)(0);
    const auto& m = impact.map;
    phase.x = contactState(theta, m.dtheta_plus, phase.x(0), m.base_velocity,
                           c.controller.memorySize(Phase::kDsp));
    e_velocity = m.leading.slides ? m.leading.velocity(0) : 0.0;
    rec.e_anchor = swingTipOf(c, phase.x)(0);
    if (phase.failure.empty() && r.impact == "double" && c.ref.hasDsp()) {
      rec.e_on_ground = true;
      const double begin = c.ref.dspClockAt(theta);
      const PhaseStart dsp_start = c.ref.startFrom(Phase::kDsp, begin, theta, m.dtheta_plus);
      phase.x.tail(c.controller.memorySize(Phase::kDsp)) =
          c.controller.phaseStartMemory(Phase::kDsp, theta, m.dtheta_plus,
                                        c.ref.at(Phase::kDsp, begin, dsp_start), &single_support);
      const ContactSet both{afterImpact(m.trailing), afterImpact(m.leading)};
      phase = runPhase(c, rec, Phase::kDsp, dsp_start, both, begin, phase.x, {c.ref.endTime()},
                       t0 + r.ssp_duration - begin);
      r.dsp_duration = phase.t - begin;
      const State end =
          ContactLoop(c.plant, c.controller, c.ref, Phase::kDsp, dsp_start, phase.contacts, c.rules)
              .at(phase.t, phase.x);
      e_velocity = phase.contacts.e.mode == TipContact::Mode::kSlide
                       ? tangentialVelocity(c, end, true)
                       : 0.0;
    }
  }
  r.failure = phase.failure;
  r.ok = r.failure.empty();
  r.theta = anglesOf(c, phase.x);
  r.dtheta = ratesOf(c, phase.x);
  if (!r.ok) return r;
  r.advance = swingTipOf(c, phase.x)(0);  // lift-off: E becomes the stance
  r.stance_velocity = e_velocity;
  r.theta = dynamics::relabelAngles<double>(c.plant, r.theta);
  r.dtheta = dynamics::relabelRates<double>(r.dtheta);
  return r;
}

ContactSet stepStartContacts(double stance_velocity) {
  return {stance_velocity != 0 ? TipContact::slide(stance_velocity > 0 ? 1.0 : -1.0)
                               : TipContact::stick(),
          TipContact::free()};
}

}  // namespace

StepResult simulateStep(const dynamics::Model& plant, const Controller& controller,
                        const Reference& ref, const VecD& theta0, const VecD& dtheta0,
                        const EventIntegratorOptions& o, const WalkLog& log, double t0,
                        int step_index, double stance_x, const std::optional<Push>& push,
                        const ContactRules& rules, double stance_velocity) {
  StepResult r = rigidStepResult();
  const StepContext c{plant, controller, ref, o, rules, push, step_index};
  StepRecorder rec{r, log, step_index, stance_x};
  return finishStep(c, rec, ref.startFrom(Phase::kSsp, 0, theta0, dtheta0),
                    stepStartContacts(stance_velocity), 0,
                    contactState(theta0, dtheta0, 0, Vec2d(stance_velocity, 0),
                                 controller.memorySize(Phase::kSsp)),
                    t0);
}

StepResult simulateStepFrom(const dynamics::Model& plant, const Controller& controller,
                            const Reference& ref, const SspState& s,
                            const EventIntegratorOptions& o, const ContactRules& rules,
                            const std::optional<Push>& push) {
  if (s.clock < ref.fadeTime())
    throw std::invalid_argument(
        "a step taken up in single support must start past the fade of "
        "the step's start (reference.hpp)");
  StepResult r = rigidStepResult();
  const StepContext c{plant, controller, ref, o, rules, push, 0};
  StepRecorder rec{r, {}, 0, 0};
  Eigen::VectorXd x = contactState(s.theta, s.dtheta, 0, Vec2d::Zero(), 0);
  x.conservativeResize(x.size() + s.memory.size());
  x.tail(s.memory.size()) = s.memory;
  // Past the fade the reference no longer depends on the step's start: no offset to carry.
  return finishStep(c, rec, PhaseStart{s.clock, 0, {}, {}}, stepStartContacts(0), s.clock, x, 0);
}

SspRun simulateSingleSupportTo(const dynamics::Model& plant, const Controller& controller,
                               const Reference& ref, const VecD& theta0, const VecD& dtheta0,
                               double clock, const EventIntegratorOptions& o,
                               const ContactRules& rules, double stance_velocity) {
  StepResult r = rigidStepResult();
  const std::optional<Push> no_push;
  const StepContext c{plant, controller, ref, o, rules, no_push, 0};
  StepRecorder rec{r, {}, 0, 0};
  const PhaseEnd end = runPhase(c, rec, Phase::kSsp, ref.startFrom(Phase::kSsp, 0, theta0, dtheta0),
                                stepStartContacts(stance_velocity), 0,
                                contactState(theta0, dtheta0, 0, Vec2d(stance_velocity, 0),
                                             controller.memorySize(Phase::kSsp)),
                                {clock}, 0);
  SspRun run;
  run.failure = !end.failure.empty() ? end.failure
                : !end.event.empty() ? "touchdown before the section's clock"
                : end.contacts.b.mode != TipContact::Mode::kStick
                    ? "the stance tip slides at the section"
                    : "";
  run.ok = run.failure.empty();
  run.state = {end.t, anglesOf(c, end.x), ratesOf(c, end.x), contactMemory(end.x, c.n())};
  return run;
}

}  // namespace gaitopt::sim
