#include "ocp/problem/gait_problem.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <stdexcept>

#include "dynamics/dsp_dynamics.hpp"
#include "dynamics/ground.hpp"
#include "dynamics/joint_coordinates.hpp"
#include "ocp/problem/dsp_chart.hpp"
#include "ocp/problem/gait_links.hpp"
#include "ocp/problem/ground_contact.hpp"
#include "ocp/problem/jerk_limit.hpp"
#include "ocp/problem/path_functions.hpp"
#include "ocp/problem/quarter_work.hpp"
#include "ocp/solve/dsp_chart_export.hpp"
#include "ocp/transcription/autodiff_constraint.hpp"
#include "ocp/transcription/biped_dynamics.hpp"
#include "ocp/transcription/collocation_interpolation.hpp"

namespace gaitopt::ocp {
namespace {

using Bounds = std::pair<Eigen::VectorXd, Eigen::VectorXd>;

/// Bounds of one point from the robot and switches.
Bounds pointBounds(const dynamics::Model& model, const OcpConfig& c, const PointLayout& l) {
  const int n = l.n;
  Eigen::VectorXd lo = Eigen::VectorXd::Constant(l.size(), -kInf);
  Eigen::VectorXd hi = Eigen::VectorXd::Constant(l.size(), kInf);
  for (int i = 0; i < n; ++i) {
    if (c.angle_range > 0) {  // |theta - upright|, upright = pi for the hanging swing leg
      const double up = i >= n - model.legLinks() ? std::numbers::pi : 0.0;
      lo(l.q[i]) = up - c.angle_range;
      hi(l.q[i]) = up + c.angle_range;
    }
    if (c.rate_limit > 0) {
      lo(l.v[i]) = -c.rate_limit;
      hi(l.v[i]) = c.rate_limit;
    }
    const auto& joint = model.joints()[static_cast<size_t>(i)];
    const double limit = !joint.actuated ? 0.0 : (c.torque_limits ? joint.torque_limit : kInf);
    lo(l.u[i]) = -limit;
    hi(l.u[i]) = limit;
  }
  l.work_plus.of(lo).setZero();  // s+, s- >= 0
  l.work_minus.of(lo).setZero();
  return {lo, hi};
}

/// The guess at phase time t: the SSP side of the touchdown for the SSP, the DSP side after;
/// work slacks split the guess's joint power into its positive and negative parts.
Eigen::VectorXd guessPoint(const gaits::Trajectory& guess, const Phase& phase, double t) {
  const double ssp_end = guess.phaseDurations().front().second;
  const double at =
      phase.doubleSupport() ? std::min(ssp_end + t, guess.endTime()) : std::min(t, ssp_end - 1e-9);
  const gaits::Knot k = guess.at(at);
  const PointLayout& l = phase.point;
  Eigen::VectorXd v(l.size());
  l.q.of(v) = k.theta;
  l.v.of(v) = k.dtheta;
  l.a.of(v) = k.ddtheta;
  l.u.of(v) = k.tau;
  l.lambda.of(v) = k.force_swing.head(l.lambda.size);
  if (l.hasWorkSlacks()) {
    const Eigen::VectorXd power = k.tau.cwiseProduct(dynamics::toJoint<double>(VecD(k.dtheta)));
    l.work_plus.of(v) = power.cwiseMax(0.0);
    l.work_minus.of(v) = (-power).cwiseMax(0.0);
  }
  return v;
}

/// y = (a, b) -> b - a: one block of variables continues into another.
struct Continuity {
  template <class S>
  dynamics::VecX<S> operator()(const dynamics::VecX<S>& y) const {
    const auto half = y.size() / 2;
    return y.tail(half) - y.head(half);
  }
};

/// A free duration T is a variable of its own, ahead of the phase's points.
int addDuration(GaitProblem& p, const PhaseConfig& config, const std::string& phase) {
  if (!config.freeDuration()) return -1;
  return p.nlp
      .addVariables(phase + "_duration", 1, Eigen::VectorXd::Constant(1, config.duration_min),
                    Eigen::VectorXd::Constant(1, config.duration_max),
                    Eigen::VectorXd::Constant(1, config.duration), phase)
      .offset;
}

Phase addPhase(GaitProblem& p, const dynamics::Model& model, const OcpConfig& c,
               const gaits::Trajectory& guess, const PhaseConfig& config, gaits::Phase kind) {
  const int n = model.nLinks();
  Phase phase;
  phase.kind = kind;
  phase.reduced_coordinates = phase.doubleSupport() && c.dsp_reduced_coordinates;
  phase.point = PointLayout::biped(n, phase.doubleSupport(), c.cost.needsWorkSlacks());
  phase.layout = PhaseLayout{.scheme = c.scheme,
                             .segments = config.segments,
                             .duration = config.duration,
                             .nx = phase.point.stateSize(),
                             .nu = phase.point.u.size,
                             .nz = phase.point.algebraicSize(),
                             .nq = phase.point.q.size,
                             .mesh = config.mesh};
  PhaseLayout& l = phase.layout;
  l.validate();
  l.duration_index = addDuration(p, config, phase.name());
  const auto [lo, hi] = pointBounds(model, c, phase.point);
  Eigen::VectorXd x0(l.variables());
  for (int k = 0; k < l.points(); ++k)
    x0.segment(l.pointOffset(k) - l.offset, l.pointSize()) = guessPoint(guess, phase, l.time(k));
  l.offset = p.nlp
                 .addVariables(phase.name() + "_points", l.variables(), lo.replicate(l.points(), 1),
                               hi.replicate(l.points(), 1), x0, phase.name(), l.pointSize())
                 .offset;
  return phase;
}

void addPathConstraint(GaitProblem& p, const Phase& phase, const std::string& what,
                       std::shared_ptr<const PointFunction> f) {
  p.nlp.addConstraint(std::make_unique<PathConstraint>(phase.name() + "_" + what, phase.name(),
                                                       phase.layout, std::move(f)));
}

/// The weighted running costs: torque squared, and absolute work through slacks, alone or
/// per weight and step length (cost of transport, W / (m g d)).
void addPhaseCost(GaitProblem& p, const dynamics::Model& model, const OcpConfig& c,
                  const Phase& phase) {
  if (c.cost.torque_squared > 0)
    p.nlp.addCost(std::make_unique<QuadratureCost>(
        phase.name() + "_torque_squared", phase.layout,
        std::make_shared<TorqueSquared>(phase.point, c.cost.torque_squared)));
  if (!phase.point.hasWorkSlacks()) return;
  addPathConstraint(p, phase, "work_split", std::make_shared<WorkSplit>(phase.point));
  const double weight = c.cost.abs_work + c.cost.cost_of_transport /
                                              (model.totalMass() * model.gravity() * c.step_length);
  // Hermite-Simpson: the work is also split at the segments' quarter points (quarter_work.hpp),
  // so it holds between the points; the points then carry the five-point rule's weights.
  const bool quarters = phase.layout.scheme == Scheme::kHermiteSimpson;
  p.nlp.addCost(std::make_unique<QuadratureCost>(
      phase.name() + "_abs_work", phase.layout, std::make_shared<AbsoluteWork>(phase.point, weight),
      quarters ? fivePointWeights(phase.layout) : Eigen::VectorXd()));
  if (quarters) addQuarterWork(p.nlp, phase, weight);
}

void addPhaseConstraints(GaitProblem& p, const dynamics::Model& model, const OcpConfig& c,
                         const Phase& phase) {
  if (phase.reduced_coordinates)
    addReducedDsp(p.nlp, model, phase, p.step_length);
  else
    p.nlp.addConstraint(std::make_unique<CollocationDefects>(phase.name() + "_defects",
                                                             phase.name(), phase.layout));
  addPathConstraint(p, phase, "dynamics", std::make_shared<BipedDynamics>(model, phase.point));
  if (c.jerk_limit > 0)
    p.nlp.addConstraint(std::make_unique<JerkLimit>(phase.name() + "_jerk", phase, c.jerk_limit));
  if (c.joint_velocity_limits)
    addPathConstraint(p, phase, "joint_rates",
                      std::make_shared<JointRateLimits>(model, phase.point));
  if (c.knee_limits && model.legLinks() == 2)
    addPathConstraint(p, phase, "knees", std::make_shared<KneeDirection>(phase.point));
  if (c.ground_contact) {
    // The ZMP rows only bound an ankle torque, so a passive ankle has none.
    const auto zmp_foot = c.zmp && model.joints().front().actuated
                              ? std::optional<dynamics::Foot>(marginFoot(model, c))
                              : std::nullopt;
    addPathConstraint(p, phase, "ground_contact",
                      std::make_shared<GroundContact>(model, phase.point, zmp_foot, p.step_length,
                                                      frictionBound(model, c)));
  }
  if (!phase.doubleSupport() && c.clearance.enabled)
    p.nlp.addConstraint(std::make_unique<SwingClearance>(model, phase, c.clearance));
  addPhaseCost(p, model, c, phase);
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
  std::vector<int> free;
  double fixed = 0;
  for (const Phase* phase : p.phases()) {
    if (phase->layout.freeDuration())
      free.push_back(phase->layout.duration_index);
    else
      fixed += phase->layout.duration;
  }
  addLink(p.nlp, "step_duration", 1, free, 0, DurationSum{fixed}, step_duration, step_duration);
}

}  // namespace

GaitProblem buildGaitProblem(const dynamics::Model& model, const OcpConfig& config,
                             const gaits::Trajectory& guess) {
  if (guess.nLinks() != model.nLinks())
    throw std::invalid_argument("initial guess and robot have different numbers of links");
  GaitProblem p;
  p.step_length = config.step_length;
  p.ssp = addPhase(p, model, config, guess, config.phases.front(), gaits::Phase::kSsp);
  addPhaseConstraints(p, model, config, p.ssp);
  p.touchdown = Touchdown::add(p.nlp, model, config, p.ssp, p.step_length);
  std::vector<int> end_state = concat(p.ssp.indices(-1, p.ssp.point.q), p.touchdown.ratesAfter());
  if (config.phases.size() == 2) {
    p.dsp = addPhase(p, model, config, guess, config.phases.back(), gaits::Phase::kDsp);
    addPhaseConstraints(p, model, config, *p.dsp);
    const Phase& dsp = *p.dsp;
    const std::vector<int> dsp_start =
        concat(dsp.indices(0, dsp.point.q), dsp.indices(0, dsp.point.v));
    // The DSP starts where the touchdown left the robot.
    addLink(p.nlp, "touchdown_to_dsp", dsp.point.stateSize(), concat(end_state, dsp_start), 0,
            Continuity{});
    end_state = concat(dsp.indices(-1, dsp.point.q), dsp.indices(-1, dsp.point.v));
  }
  const std::vector<int> start =
      concat(p.ssp.indices(0, p.ssp.point.q), p.ssp.indices(0, p.ssp.point.v));
  addLink(p.nlp, "periodicity", p.ssp.point.stateSize(), concat(end_state, start), 0,
          Periodicity{&model});
  if (config.step_duration > 0) addStepDuration(p, config.step_duration);
  return p;
}

namespace {

/// A knot from one point's variables (PointLayout).
gaits::Knot knotOf(const Eigen::VectorXd& v, const dynamics::Model& model, const Phase& phase,
                   double t) {
  const PointLayout& l = phase.point;
  gaits::Knot knot;
  knot.t = t;
  knot.phase = phase.kind;
  knot.theta = l.q.of(v);
  knot.dtheta = l.v.of(v);
  knot.ddtheta = l.a.of(v);
  knot.tau = l.u.of(v);
  if (l.hasContactForce()) knot.force_swing = l.lambda.of(v);
  knot.force_stance =
      dynamics::stanceForce<double>(model, knot.theta, knot.dtheta, knot.ddtheta, knot.force_swing);
  return knot;
}

void appendKnots(std::vector<gaits::Knot>& knots, const Phase& phase, const dynamics::Model& model,
                 const Eigen::VectorXd& x, double t0) {
  const PhaseLayout& l = phase.layout;
  for (int k = 0; k < l.points(); ++k)
    knots.push_back(knotOf(l.point(x, k), model, phase, t0 + l.time(k, l.durationAt(x))));
}

bool fullyActuated(const dynamics::Model& model) {
  return std::all_of(model.joints().begin(), model.joints().end(),
                     [](const auto& joint) { return joint.actuated; });
}

/// What a phase's export needs; a double support in reduced coordinates is exported on its
/// chart (dsp_chart_export.hpp).
struct PhaseExport {
  const Phase& phase;
  const Eigen::VectorXd& x;
  double step_length;
  std::optional<ChartTrack> chart;  ///< reduced coordinates only
};

/// An exported knot: the scheme's polynomials, with rates that are the derivatives of the
/// angles (exportPoint). A fully actuated robot gets the torques that produce this motion
/// exactly, Mu (2.43) in the SSP and (2.11) with the interpolated tip force in the DSP: the
/// scheme's own quadratic torques miss the dynamics between the points (by 3.2 N m, 8 % of the
/// peak torque, on the default optimum), which a controller's feed-forward would inherit. An
/// underactuated chain has no such torques; it keeps the scheme's, and summary.json reports
/// the residual.
gaits::Knot exportKnot(const PhaseExport& e, const dynamics::Model& model, double t, double t0) {
  const Phase& phase = e.phase;
  Eigen::VectorXd point = exportPoint(phase.layout, e.x, t);
  if (e.chart) placeOnChart(model, e.step_length, *e.chart, t, phase.point, point);
  gaits::Knot knot = knotOf(point, model, phase, t0 + t);
  if (!fullyActuated(model)) return knot;
  const VecD theta = knot.theta, dtheta = knot.dtheta, ddtheta = knot.ddtheta;
  knot.tau = phase.doubleSupport() ? dynamics::dspInverseDynamics(model, theta, dtheta, ddtheta,
                                                                  Vec2d(knot.force_swing))
                                   : dynamics::sspInverseDynamics(model, theta, dtheta, ddtheta);
  return knot;
}

/// Knots on the grid j / rate_hz inside the phase plus both ends (exportKnot); the grid is the
/// step's, not restarted at the phase start.
void appendDenseKnots(std::vector<gaits::Knot>& knots, const Phase& phase,
                      const dynamics::Model& model, const Eigen::VectorXd& x, double step_length,
                      double t0, double rate_hz) {
  const double total = phase.layout.durationAt(x);
  const double gap = 1e-3 / rate_hz;  // no sliver next to an end
  PhaseExport e{phase, x, step_length, std::nullopt};
  if (phase.reduced_coordinates) e.chart = chartTrack(model, phase, x);
  auto add = [&](double t) { knots.push_back(exportKnot(e, model, t, t0)); };
  add(0.0);
  for (auto j = static_cast<long>(std::floor(t0 * rate_hz)) + 1;; ++j) {
    const double t = static_cast<double>(j) / rate_hz - t0;
    if (t > total - gap) break;
    if (t <= gap) continue;
    add(t);
    // Exactly on the export grid (gaits/trajectory/grid_export.hpp), which then takes this knot as
    // it is rather than a quintic re-interpolation an ulp away from t0 + (j / rate - t0).
    knots.back().t = static_cast<double>(j) / rate_hz;
  }
  add(total);
}

}  // namespace

gaits::Trajectory reconstruct(const GaitProblem& problem, const dynamics::Model& model,
                              const Eigen::VectorXd& x) {
  std::vector<gaits::Knot> knots;
  double t0 = 0;
  for (const Phase* phase : problem.phases()) {
    appendKnots(knots, *phase, model, x, t0);
    t0 += phase->layout.durationAt(x);
  }
  return gaits::Trajectory(model.name(), problem.step_length, std::move(knots));
}

gaits::Trajectory reconstructDense(const GaitProblem& problem, const dynamics::Model& model,
                                   const Eigen::VectorXd& x, double rate_hz) {
  if (!(rate_hz > 0)) throw std::invalid_argument("the sample rate must be positive");
  std::vector<gaits::Knot> knots;
  double t0 = 0;
  for (const Phase* phase : problem.phases()) {
    appendDenseKnots(knots, *phase, model, x, problem.step_length, t0, rate_hz);
    t0 += phase->layout.durationAt(x);
  }
  return gaits::Trajectory(model.name(), problem.step_length, std::move(knots));
}

}  // namespace gaitopt::ocp
