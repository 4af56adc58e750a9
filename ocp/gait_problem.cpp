#include "ocp/gait_problem.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "dynamics/ground.hpp"
#include "dynamics/impact.hpp"
#include "dynamics/joint_coordinates.hpp"
#include "ocp/autodiff_constraint.hpp"
#include "ocp/biped_dynamics.hpp"
#include "ocp/collocation_interpolation.hpp"
#include "ocp/gait_links.hpp"
#include "ocp/ground_contact.hpp"
#include "ocp/path_functions.hpp"

namespace gaitopt::ocp {
namespace {

constexpr double kInf = 1e20;
using Bounds = std::pair<Eigen::VectorXd, Eigen::VectorXd>;
using Indices = std::vector<int>;

bool absWork(const OcpConfig& c) {
  return c.cost.needsWorkSlacks();
}

/// The friction coefficient of the optimiser's cones: the robot's, less the configured margin.
/// @throws std::invalid_argument when the margin leaves no cone.
double frictionBound(const dynamics::Model& model, const OcpConfig& c) {
  const double mu = model.friction() - c.friction_margin;
  if (!(mu > 0))
    throw std::invalid_argument("friction_margin must be below the robot's friction coefficient");
  return mu;
}

/// Algebraic variables of a point: lambda (DSP), then the work slacks s+, s- (abs_work cost).
int algebraicSize(const OcpConfig& c, bool dsp, int n) {
  return (dsp ? 2 : 0) + (absWork(c) ? 2 * n : 0);
}

/// Where the work slacks start in a point [theta, dtheta, ddtheta, tau, (lambda), s+, s-].
int slackOffset(bool dsp, int n) {
  return 4 * n + (dsp ? 2 : 0);
}

/// Bounds of one point from the robot and switches.
Bounds pointBounds(const dynamics::Model& model, const OcpConfig& c, bool dsp) {
  const int n = model.nLinks();
  const int size = 4 * n + algebraicSize(c, dsp, n);
  Eigen::VectorXd lo = Eigen::VectorXd::Constant(size, -kInf);
  Eigen::VectorXd hi = Eigen::VectorXd::Constant(size, kInf);
  for (int i = 0; i < n; ++i) {
    if (c.angle_range > 0) {  // |theta - upright|, upright = pi for the hanging swing leg
      const double up = i >= n - model.legLinks() ? std::numbers::pi : 0.0;
      lo(i) = up - c.angle_range;
      hi(i) = up + c.angle_range;
    }
    if (c.rate_limit > 0) {
      lo(n + i) = -c.rate_limit;
      hi(n + i) = c.rate_limit;
    }
    const auto& joint = model.joints()[static_cast<size_t>(i)];
    const double limit = !joint.actuated ? 0.0 : (c.torque_limits ? joint.torque_limit : kInf);
    lo(3 * n + i) = -limit;
    hi(3 * n + i) = limit;
  }
  if (absWork(c)) lo.tail(2 * n).setZero();  // s+, s- >= 0
  return {lo, hi};
}

/// The guess at phase time t: the SSP side of the touchdown for the SSP, the DSP side after;
/// work slacks split the guess's joint power into its positive and negative parts.
Eigen::VectorXd guessPoint(const gaits::Trajectory& guess, const OcpConfig& c, double t, bool dsp,
                           int n) {
  const double ssp_end = guess.phaseDurations().front().second;
  const double at = dsp ? std::min(ssp_end + t, guess.endTime()) : std::min(t, ssp_end - 1e-9);
  const gaits::Knot k = guess.at(at);
  Eigen::VectorXd v(4 * n + algebraicSize(c, dsp, n));
  v.head(4 * n) << k.theta, k.dtheta, k.ddtheta, k.tau;
  if (dsp) v.segment<2>(4 * n) = k.force_swing;
  if (absWork(c)) {
    const Eigen::VectorXd power = k.tau.cwiseProduct(dynamics::toJoint<double>(VecD(k.dtheta)));
    v.segment(slackOffset(dsp, n), n) = power.cwiseMax(0.0);
    v.segment(slackOffset(dsp, n) + n, n) = (-power).cwiseMax(0.0);
  }
  return v;
}

/// Impact variables [qdot+, P_E (, P_B)] from the closed-form maps at the strike state.
Eigen::VectorXd guessImpact(const dynamics::Model& model, const Eigen::VectorXd& strike,
                            bool both) {
  const int n = model.nLinks();
  const VecD theta = strike.head(n), dtheta = strike.segment(n, n);
  const auto r = both ? dynamics::doubleImpact(model, theta, dtheta)
                      : dynamics::singleImpact(model, theta, dtheta);
  Eigen::VectorXd v(n + 4 + (both ? 2 : 0));
  v.head(n + 4) << r.trailing_velocity, r.dtheta_plus, r.impulse_leading;
  if (both) v.tail(2) = r.impulse_trailing;
  return v;
}

Indices range(int first, int count) {
  Indices idx(static_cast<size_t>(count));
  for (int i = 0; i < count; ++i) idx[static_cast<size_t>(i)] = first + i;
  return idx;
}

Indices concat(Indices a, const Indices& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

/// A link constraint on `idx`; the functor is affine in all but the first `nonlinear` of them.
template <class Fn>
void addLink(Nlp& nlp, const std::string& name, int rows, Indices idx, int nonlinear, Fn fn,
             double lo = 0.0, double hi = 0.0) {
  nlp.addConstraint(std::make_unique<AutoDiffConstraint<Fn>>(
      name, rows, std::move(idx), nonlinear, fn, Eigen::VectorXd::Constant(rows, lo),
      Eigen::VectorXd::Constant(rows, hi)));
}

/// y = (a, b) -> b - a: one block of variables continues into another.
struct Continuity {
  template <class S>
  dynamics::VecX<S> operator()(const dynamics::VecX<S>& y) const {
    const auto half = y.size() / 2;
    return y.tail(half) - y.head(half);
  }
};

/// y = (a (4 rows: P_E then P_B)): impulses inside their friction cones, pushing up.
struct ImpulseCones {
  double mu;
  template <class S>
  dynamics::VecX<S> operator()(const dynamics::VecX<S>& y) const {
    dynamics::VecX<S> g(6);
    for (int tip = 0; tip < 2; ++tip) {
      const S px = y(2 * tip), py = y(2 * tip + 1);
      g.segment(3 * tip, 3) << py, mu * py - px, mu * py + px;
    }
    return g;
  }
};

/// A free duration T is a variable of its own, ahead of the phase's points.
int addDuration(GaitProblem& p, const PhaseConfig& phase, bool dsp) {
  if (!phase.freeDuration()) return -1;
  return p.nlp
      .addVariables(dsp ? "dsp_duration" : "ssp_duration", 1,
                    Eigen::VectorXd::Constant(1, phase.duration_min),
                    Eigen::VectorXd::Constant(1, phase.duration_max),
                    Eigen::VectorXd::Constant(1, phase.duration))
      .offset;
}

PhaseLayout addPhase(GaitProblem& p, const dynamics::Model& model, const OcpConfig& c,
                     const gaits::Trajectory& guess, const PhaseConfig& phase, bool dsp) {
  const int n = model.nLinks();
  PhaseLayout l{.scheme = c.scheme,
                .segments = phase.segments,
                .duration = phase.duration,
                .nx = 2 * n,
                .nu = n,
                .nz = algebraicSize(c, dsp, n),
                .nq = n,
                .mesh = phase.mesh};
  l.validate();
  l.duration_index = addDuration(p, phase, dsp);
  const auto [lo, hi] = pointBounds(model, c, dsp);
  Eigen::VectorXd x0(l.variables());
  for (int k = 0; k < l.points(); ++k)
    x0.segment(k * l.pointSize(), l.pointSize()) = guessPoint(guess, c, l.time(k), dsp, n);
  l.offset = p.nlp
                 .addVariables(dsp ? "dsp_points" : "ssp_points", l.variables(),
                               lo.replicate(l.points(), 1), hi.replicate(l.points(), 1), x0)
                 .offset;
  return l;
}

/// The weighted running costs: torque squared, and absolute work through slacks, alone or
/// per weight and step length (cost of transport, W / (m g d)).
void addPhaseCost(GaitProblem& p, const dynamics::Model& model, const OcpConfig& c,
                  const PhaseLayout& l, bool dsp) {
  const int n = model.nLinks();
  const std::string phase = dsp ? "dsp" : "ssp";
  if (c.cost.torque_squared > 0)
    p.nlp.addCost(std::make_unique<QuadratureCost>(
        phase + "_torque_squared", l, std::make_shared<TorqueSquared>(n, c.cost.torque_squared)));
  if (!absWork(c)) return;
  p.nlp.addConstraint(std::make_unique<PathConstraint>(
      phase + "_work_split", l, std::make_shared<WorkSplit>(n, slackOffset(dsp, n))));
  const double weight = c.cost.abs_work + c.cost.cost_of_transport /
                                              (model.totalMass() * model.gravity() * c.step_length);
  p.nlp.addCost(std::make_unique<QuadratureCost>(
      phase + "_abs_work", l, std::make_shared<AbsoluteWork>(n, slackOffset(dsp, n), weight)));
}

void addPhaseConstraints(GaitProblem& p, const dynamics::Model& model, const OcpConfig& c,
                         const PhaseLayout& l, bool dsp) {
  const int n = model.nLinks();
  const std::string phase = dsp ? "dsp" : "ssp";
  p.nlp.addConstraint(std::make_unique<CollocationDefects>(l, phase + "_defects"));
  p.nlp.addConstraint(std::make_unique<PathConstraint>(
      phase + "_dynamics", l, std::make_shared<BipedDynamics>(model, dsp)));
  if (c.knee_limits && model.legLinks() == 2)
    p.nlp.addConstraint(
        std::make_unique<PathConstraint>(phase + "_knees", l, std::make_shared<KneeDirection>(n)));
  if (c.ground_contact) {
    const bool zmp = c.zmp && model.joints().front().actuated;
    p.nlp.addConstraint(std::make_unique<PathConstraint>(
        phase + "_ground_contact", l,
        std::make_shared<GroundContact>(model, dsp, zmp, p.step_length, frictionBound(model, c))));
  }
  if (!dsp && c.clearance.enabled)
    p.nlp.addConstraint(std::make_unique<SwingClearance>(model, l, c.clearance));
  addPhaseCost(p, model, c, l, dsp);
}

/// Touchdown at the end of the SSP: position, strike direction, impact; returns the indices of
/// the rates right after it.
Indices addTouchdown(GaitProblem& p, const dynamics::Model& model, const OcpConfig& c) {
  const int n = model.nLinks();
  const int last = p.ssp.points() - 1;
  const Indices theta_end = range(p.ssp.x(last, 0), n);
  const Indices dtheta_end = range(p.ssp.x(last, n), n);
  const Indices strike = concat(theta_end, dtheta_end);
  // Every link is nonlinear in the strike angles only (the first n of its variables).
  addLink(p.nlp, "touchdown_position", 2, theta_end, n, TipAtTouchdown{&model, p.step_length});
  if (c.impact == ImpactModel::kImpactless) {
    addLink(p.nlp, "touchdown_at_rest", 2, strike, n, StrikeVelocity{&model, false});
    return dtheta_end;
  }
  if (c.swing_descends)
    addLink(p.nlp, "strike_downward", 1, strike, n, StrikeVelocity{&model, true}, -kInf, 0.0);
  const bool both = c.impact == ImpactModel::kDouble;
  const int size = n + 4 + (both ? 2 : 0);
  Eigen::VectorXd lo = Eigen::VectorXd::Constant(size, -kInf), hi = -lo;
  if (!both && c.trailing_lifts) lo(1) = 0;  // the old stance tip leaves the ground
  p.impact_offset =
      p.nlp
          .addVariables("impact", size, lo, hi,
                        guessImpact(model, p.ssp.point(p.nlp.initialGuess(), last), both))
          .offset;
  addLink(p.nlp, "impact", size, concat(strike, range(p.impact_offset, size)), n,
          RigidImpact{&model, both});
  if (both && c.ground_contact)
    addLink(p.nlp, "impulse_cones", 6, range(p.impact_offset + n + 2, 4), 0,
            ImpulseCones{frictionBound(model, c)}, 0.0, kInf);
  return range(p.impact_offset + 2, n);
}

/// y = free durations: their sum plus the fixed ones equals the step duration.
struct DurationSum {
  double fixed;
  template <class S>
  dynamics::VecX<S> operator()(const dynamics::VecX<S>& y) const {
    return dynamics::VecX<S>::Constant(1, y.sum() + fixed);
  }
};

void addStepDuration(GaitProblem& p, double step_duration) {
  Indices free;
  double fixed = 0;
  for (const PhaseLayout* l : {&p.ssp, p.dsp ? &*p.dsp : nullptr}) {
    if (l == nullptr) continue;
    if (l->freeDuration())
      free.push_back(l->duration_index);
    else
      fixed += l->duration;
  }
  addLink(p.nlp, "step_duration", 1, free, 0, DurationSum{fixed}, step_duration, step_duration);
}

}  // namespace

GaitProblem buildGaitProblem(const dynamics::Model& model, const OcpConfig& config,
                             const gaits::Trajectory& guess) {
  if (guess.nLinks() != model.nLinks())
    throw std::invalid_argument("initial guess and robot have different numbers of links");
  const int n = model.nLinks();
  GaitProblem p;
  p.step_length = config.step_length;
  p.ssp = addPhase(p, model, config, guess, config.phases.front(), false);
  addPhaseConstraints(p, model, config, p.ssp, false);
  const int last = p.ssp.points() - 1;
  Indices theta_end = range(p.ssp.x(last, 0), n);
  Indices rates_end = addTouchdown(p, model, config);
  if (config.phases.size() == 2) {
    p.dsp = addPhase(p, model, config, guess, config.phases.back(), true);
    addPhaseConstraints(p, model, config, *p.dsp, true);
    // The DSP starts where the touchdown left the robot.
    addLink(p.nlp, "touchdown_to_dsp", 2 * n,
            concat(concat(theta_end, rates_end), range(p.dsp->x(0, 0), 2 * n)), 0, Continuity{});
    const int dsp_last = p.dsp->points() - 1;
    theta_end = range(p.dsp->x(dsp_last, 0), n);
    rates_end = range(p.dsp->x(dsp_last, n), n);
  }
  addLink(p.nlp, "periodicity", 2 * n,
          concat(concat(theta_end, rates_end), range(p.ssp.x(0, 0), 2 * n)), 0,
          Periodicity{&model});
  if (config.step_duration > 0) addStepDuration(p, config.step_duration);
  return p;
}

namespace {

/// A knot from one point's variables [theta, dtheta, ddtheta, tau, (lambda), ...].
gaits::Knot knotOf(const Eigen::VectorXd& v, const dynamics::Model& model, bool dsp, double t) {
  const int n = model.nLinks();
  gaits::Knot knot;
  knot.t = t;
  knot.phase = dsp ? gaits::Phase::kDsp : gaits::Phase::kSsp;
  knot.theta = v.segment(0, n);
  knot.dtheta = v.segment(n, n);
  knot.ddtheta = v.segment(2 * n, n);
  knot.tau = v.segment(3 * n, n);
  if (dsp) knot.force_swing = v.segment<2>(4 * n);
  knot.force_stance =
      dynamics::stanceForce<double>(model, knot.theta, knot.dtheta, knot.ddtheta, knot.force_swing);
  return knot;
}

void appendKnots(std::vector<gaits::Knot>& knots, const PhaseLayout& l,
                 const dynamics::Model& model, const Eigen::VectorXd& x, bool dsp, double t0) {
  for (int k = 0; k < l.points(); ++k)
    knots.push_back(knotOf(l.point(x, k), model, dsp, t0 + l.time(k, l.durationAt(x))));
}

/// Knots on the grid j / rate_hz inside the phase plus both ends, from the scheme's own
/// polynomials.
void appendDenseKnots(std::vector<gaits::Knot>& knots, const PhaseLayout& l,
                      const dynamics::Model& model, const Eigen::VectorXd& x, bool dsp, double t0,
                      double rate_hz) {
  const double total = l.durationAt(x);
  const double gap = 1e-3 / rate_hz;  // no sliver next to an end
  auto add = [&](double t) {
    knots.push_back(knotOf(interpolatePoint(l, x, t), model, dsp, t0 + t));
  };
  add(0.0);
  for (auto j = static_cast<long>(std::floor(t0 * rate_hz)) + 1;; ++j) {
    const double t = static_cast<double>(j) / rate_hz - t0;
    if (t > total - gap) break;
    if (t > gap) add(t);
  }
  add(total);
}

}  // namespace

gaits::Trajectory reconstruct(const GaitProblem& problem, const dynamics::Model& model,
                              const Eigen::VectorXd& x) {
  std::vector<gaits::Knot> knots;
  appendKnots(knots, problem.ssp, model, x, false, 0.0);
  if (problem.dsp) appendKnots(knots, *problem.dsp, model, x, true, problem.ssp.durationAt(x));
  return gaits::Trajectory(model.name(), problem.step_length, std::move(knots));
}

gaits::Trajectory reconstructDense(const GaitProblem& problem, const dynamics::Model& model,
                                   const Eigen::VectorXd& x, double rate_hz) {
  if (!(rate_hz > 0)) throw std::invalid_argument("the sample rate must be positive");
  std::vector<gaits::Knot> knots;
  appendDenseKnots(knots, problem.ssp, model, x, false, 0.0, rate_hz);
  if (problem.dsp)
    appendDenseKnots(knots, *problem.dsp, model, x, true, problem.ssp.durationAt(x), rate_hz);
  return gaits::Trajectory(model.name(), problem.step_length, std::move(knots));
}

}  // namespace gaitopt::ocp
