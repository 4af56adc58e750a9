#include "gaits/polynomial/polynomial_gait.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include <fmt/format.h>

#include "dynamics/ground.hpp"
#include "dynamics/impact/relabel.hpp"
#include "dynamics/ssp_dynamics.hpp"
#include "gaits/polynomial/dsp_force_distribution.hpp"

namespace gaitopt::gaits {
namespace {

/// T_m of (3.4): the root of x_a(t) = S_m in (0, T_S); x_a is monotonic (3.7-3.9, 3.11), so
/// bisection is exact to rounding.
double solveApexTime(const Polynomial& x_a, double s_m, double t_s) {
  double lo = 0;
  double hi = t_s;
  for (int i = 0; i < 200 && hi - lo > 1e-15 * t_s; ++i) {
    const double mid = 0.5 * (lo + hi);
    (x_a(mid) < s_m ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

PointMotion difference(const PointMotion& a, const PointMotion& b) {
  return {a.pos - b.pos, a.vel - b.vel, a.acc - b.acc};
}

}  // namespace

void requireKneedLegs(const dynamics::Model& model) {
  dynamics::requireKneedLegs(model, "the polynomial gait (Mu ch. 3)");
}

PolynomialGait::PolynomialGait(const dynamics::Model& model, GaitParams params, HipPlan plan)
    : model_(&model), params_(std::move(params)), plan_(plan) {
  requireKneedLegs(model);
  const double l = params_.step_length;
  const double t_s = params_.ssp_duration;
  // x_a: cubic with (3.7), (3.8), (3.9), (3.11).
  x_a_ = hermiteCubic(-l, 0.0, l, 0.0, t_s);
  // T_m from (3.4); y_a: quintic with (3.2), (3.3), (3.5), (3.6), (3.10), (3.12).
  t_m_ = solveApexTime(x_a_, params_.apex_x, t_s);
  y_a_ = quinticThrough({0.0, t_m_, t_s}, {0.0, params_.apex_height, 0.0}, {0.0, 0.0, 0.0});
  // Hip: (3.16), (3.18), (3.20), (3.22) in the SSP and (3.21), (3.23), (3.17), (3.19) in the DSP.
  x_hs_ = hermiteCubic(-plan_.start, plan_.velocity_start, plan_.dsp_start,
                       plan_.velocity_touchdown, t_s);
  x_hd_ = hermiteCubic(plan_.dsp_start, plan_.velocity_touchdown, l - plan_.start,
                       plan_.velocity_start, params_.dsp_duration);
}

PointMotion PolynomialGait::swingTip(double t, Phase phase) const {
  if (phase == Phase::kDsp)
    return {Eigen::Vector2d(params_.step_length, 0.0), Eigen::Vector2d::Zero(),
            Eigen::Vector2d::Zero()};
  return {{x_a_(t), y_a_(t)}, {x_a_(t, 1), y_a_(t, 1)}, {x_a_(t, 2), y_a_(t, 2)}};
}

PointMotion PolynomialGait::hip(double t, Phase phase) const {
  const bool ssp = phase == Phase::kSsp;
  const double local = ssp ? t : t - params_.ssp_duration;
  const Polynomial& x = ssp ? x_hs_ : x_hd_;
  // y_h = H_h (3.14-3.15), optionally with a periodic bob that keeps the step repeatable.
  const double w = 2 * std::numbers::pi / params_.duration();
  const double b = params_.hip_bob;
  return {{x(local), plan_.height + b * std::cos(w * t)},
          {x(local, 1), -b * w * std::sin(w * t)},
          {x(local, 2), -b * w * w * std::cos(w * t)}};
}

bool PolynomialGait::reachable(double t, Phase phase) const {
  const int n = model_->nLinks();
  const Eigen::Vector2d h = hip(t, phase).pos;
  return legCanReach(model_->link(0).length, model_->link(1).length, h) &&
         legCanReach(model_->link(n - 2).length, model_->link(n - 1).length,
                     swingTip(t, phase).pos - h);
}

GaitKinematics PolynomialGait::kinematics(double t, Phase phase) const {
  const int n = model_->nLinks();
  const PointMotion h = hip(t, phase);
  const PointMotion tip_from_hip = difference(swingTip(t, phase), h);
  LegAngles stance, swing;
  try {
    stance = legInverseKinematics(model_->link(0).length, model_->link(1).length, h, params_.knee);
    swing = legInverseKinematics(model_->link(n - 2).length, model_->link(n - 1).length,
                                 tip_from_hip, params_.knee);
  } catch (const std::domain_error& e) {
    throw std::domain_error(
        fmt::format("{} at t = {:.4f} s ({}): {}", params_.name, t, toString(phase), e.what()));
  }
  GaitKinematics k{VecD::Zero(n), VecD::Zero(n), VecD::Zero(n)};
  k.theta.head<2>() = stance.theta;
  k.dtheta.head<2>() = stance.dtheta;
  k.ddtheta.head<2>() = stance.ddtheta;
  k.theta.tail<2>() = swing.theta;
  k.dtheta.tail<2>() = swing.dtheta;
  k.ddtheta.tail<2>() = swing.ddtheta;
  for (int i = n - 2; i < n; ++i) k.theta(i) = dynamics::wrapAngle(k.theta(i), std::numbers::pi);
  if (const auto torso = model_->torso()) k.theta(*torso) = params_.torso_angle;
  return k;
}

namespace {

Knot makeKnot(const PolynomialGait& gait, const dynamics::Model& model, double t, Phase phase) {
  const GaitKinematics k = gait.kinematics(t, phase);
  Knot knot;  // forces default to zero (Eigen's {} would leave them uninitialised)
  knot.t = t;
  knot.phase = phase;
  knot.theta = k.theta;
  knot.dtheta = k.dtheta;
  knot.ddtheta = k.ddtheta;
  if (phase == Phase::kSsp) {
    knot.tau = dynamics::sspInverseDynamics(model, k.theta, k.dtheta, k.ddtheta);
    knot.force_stance =
        dynamics::stanceForce<double>(model, k.theta, k.dtheta, k.ddtheta, Vec2d::Zero());
    return knot;
  }
  const DspForces f = distributeDspForces(model, k.theta, k.dtheta, k.ddtheta);
  knot.tau = f.tau;
  knot.force_stance = f.force_stance;
  knot.force_swing = f.force_swing;
  return knot;
}

}  // namespace

Trajectory buildTrajectory(const PolynomialGait& gait, const dynamics::Model& model,
                           double rate_hz) {
  if (!(rate_hz > 0)) throw std::invalid_argument("sample rate must be positive");
  const double t_s = gait.params().ssp_duration;
  const double t_end = gait.params().duration();
  std::vector<Knot> knots;
  auto add = [&](double t, Phase phase) { knots.push_back(makeKnot(gait, model, t, phase)); };
  const double eps = 1e-9 / rate_hz;  // grid points this close to a phase end are that end
  auto grid = [rate_hz](long k) { return static_cast<double>(k) / rate_hz; };
  for (long k = 0; grid(k) < t_s - eps; ++k) add(grid(k), Phase::kSsp);
  add(t_s, Phase::kSsp);  // touchdown: both knots of the switch
  add(t_s, Phase::kDsp);
  for (auto k = static_cast<long>(std::ceil((t_s + eps) * rate_hz)); grid(k) < t_end - eps; ++k)
    add(grid(k), Phase::kDsp);
  add(t_end, Phase::kDsp);
  return Trajectory(model.name(), gait.params().step_length, std::move(knots));
}

}  // namespace gaitopt::gaits
