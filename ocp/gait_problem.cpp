#include "ocp/gait_problem.hpp"

#include <numbers>
#include <stdexcept>

#include <fmt/format.h>

#include "dynamics/ground.hpp"
#include "dynamics/impact.hpp"
#include "ocp/autodiff_constraint.hpp"
#include "ocp/biped_dynamics.hpp"
#include "ocp/gait_costs.hpp"
#include "ocp/gait_links.hpp"
#include "ocp/point_function.hpp"

namespace gaitopt::ocp {
namespace {

constexpr double kInf = 1e20;
using Bounds = std::pair<Eigen::VectorXd, Eigen::VectorXd>;

/// Bounds of one point [theta, dtheta, ddtheta, tau] from the robot and the switches.
Bounds pointBounds(const dynamics::Model& model, const OcpConfig& c) {
  const int n = model.nLinks();
  Eigen::VectorXd lo = Eigen::VectorXd::Constant(4 * n, -kInf);
  Eigen::VectorXd hi = Eigen::VectorXd::Constant(4 * n, kInf);
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
  return {lo, hi};
}

Eigen::VectorXd guessPoint(const gaits::Trajectory& guess, double t, int n) {
  const gaits::Knot k = guess.at(std::min(t, guess.endTime()));
  Eigen::VectorXd v(4 * n);
  v << k.theta, k.dtheta, k.ddtheta, k.tau;
  return v;
}

/// Impact variables [qdot+, P_E (, P_B)] from the closed-form maps at the guess's strike state.
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

std::vector<int> range(int first, int count) {
  std::vector<int> idx(static_cast<size_t>(count));
  for (int i = 0; i < count; ++i) idx[static_cast<size_t>(i)] = first + i;
  return idx;
}

std::vector<int> concat(std::vector<int> a, const std::vector<int>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

/// A link constraint on `idx`; the functor is affine in all but the first `nonlinear` of them.
template <class Fn>
void addLink(Nlp& nlp, const std::string& name, int rows, std::vector<int> idx, int nonlinear,
             Fn fn, double lo = 0.0, double hi = 0.0) {
  nlp.addConstraint(std::make_unique<AutoDiffConstraint<Fn>>(
      name, rows, std::move(idx), nonlinear, fn, Eigen::VectorXd::Constant(rows, lo),
      Eigen::VectorXd::Constant(rows, hi)));
}

void addPhaseVariables(GaitProblem& p, const dynamics::Model& model, const OcpConfig& c,
                       const gaits::Trajectory& guess) {
  const int n = model.nLinks();
  const auto [lo, hi] = pointBounds(model, c);
  const int points = p.ssp.points();
  Eigen::VectorXd x0(p.ssp.variables());
  for (int k = 0; k < points; ++k)
    x0.segment(k * 4 * n, 4 * n) = guessPoint(guess, p.ssp.time(k), n);
  p.ssp.offset = p.nlp
                     .addVariables("ssp_points", p.ssp.variables(), lo.replicate(points, 1),
                                   hi.replicate(points, 1), x0)
                     .offset;
}

void addImpactVariables(GaitProblem& p, const dynamics::Model& model, const OcpConfig& c) {
  const int n = model.nLinks();
  const bool both = c.impact == ImpactModel::kDouble;
  const int size = n + 4 + (both ? 2 : 0);
  const Eigen::VectorXd strike = p.ssp.point(p.nlp.initialGuess(), p.ssp.points() - 1);
  Eigen::VectorXd lo = Eigen::VectorXd::Constant(size, -kInf);
  Eigen::VectorXd hi = Eigen::VectorXd::Constant(size, kInf);
  if (!both && c.trailing_lifts) lo(1) = 0;  // the old stance tip leaves the ground
  p.impact_offset =
      p.nlp.addVariables("impact", size, lo, hi, guessImpact(model, strike, both)).offset;
}

void addLinks(GaitProblem& p, const dynamics::Model& model, const OcpConfig& c) {
  const int n = model.nLinks();
  const bool both = c.impact == ImpactModel::kDouble;
  const int last = p.ssp.points() - 1;
  const std::vector<int> theta_end = range(p.ssp.x(last, 0), n);
  const std::vector<int> dtheta_end = range(p.ssp.x(last, n), n);
  // Every link is nonlinear in the strike angles only (the first n of its variables).
  addLink(p.nlp, "touchdown_position", 2, theta_end, n, TipAtTouchdown{&model, p.step_length});
  if (c.swing_descends)
    addLink(p.nlp, "strike_downward", 1, concat(theta_end, dtheta_end), n, StrikeVelocity{&model},
            -kInf, 0.0);
  addLink(p.nlp, "impact", n + 4 + (both ? 2 : 0),
          concat(concat(theta_end, dtheta_end), range(p.impact_offset, n + 4 + (both ? 2 : 0))), n,
          RigidImpact{&model, both});
  const std::vector<int> start = range(p.ssp.x(0, 0), 2 * n);
  addLink(p.nlp, "periodicity", 2 * n,
          concat(concat(theta_end, range(p.impact_offset + 2, n)), start), 0, Periodicity{&model});
}

}  // namespace

GaitProblem buildGaitProblem(const dynamics::Model& model, const OcpConfig& config,
                             const gaits::Trajectory& guess) {
  const PhaseConfig& phase = config.phases.front();
  if (guess.nLinks() != model.nLinks())
    throw std::invalid_argument("initial guess and robot have different numbers of links");
  const int n = model.nLinks();
  GaitProblem p;
  p.step_length = config.step_length;
  p.ssp = PhaseLayout{config.scheme, phase.segments, phase.duration, 2 * n, n, 0, 0, n};
  addPhaseVariables(p, model, config, guess);
  addImpactVariables(p, model, config);
  p.nlp.addConstraint(std::make_unique<CollocationDefects>(p.ssp, "ssp_defects"));
  p.nlp.addConstraint(std::make_unique<PathConstraint>(
      "ssp_dynamics", p.ssp, std::make_shared<BipedDynamics>(model, false)));
  if (config.knee_limits && model.legLinks() == 2)
    p.nlp.addConstraint(
        std::make_unique<PathConstraint>("knees", p.ssp, std::make_shared<KneeDirection>(n)));
  addLinks(p, model, config);
  p.nlp.addCost(std::make_unique<QuadratureCost>("torque_squared", p.ssp,
                                                 std::make_shared<TorqueSquared>(n)));
  return p;
}

gaits::Trajectory reconstruct(const GaitProblem& problem, const dynamics::Model& model,
                              const Eigen::VectorXd& x) {
  const int n = model.nLinks();
  std::vector<gaits::Knot> knots;
  for (int k = 0; k < problem.ssp.points(); ++k) {
    const Eigen::VectorXd v = problem.ssp.point(x, k);
    gaits::Knot knot;
    knot.t = problem.ssp.time(k);
    knot.theta = v.segment(0, n);
    knot.dtheta = v.segment(n, n);
    knot.ddtheta = v.segment(2 * n, n);
    knot.tau = v.segment(3 * n, n);
    knot.force_stance =
        dynamics::stanceForce<double>(model, knot.theta, knot.dtheta, knot.ddtheta, Vec2d::Zero());
    knots.push_back(std::move(knot));
  }
  return gaits::Trajectory(model.name(), problem.step_length, std::move(knots));
}

}  // namespace gaitopt::ocp
