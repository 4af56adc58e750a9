#include "sim/controllers/reference.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>
#include <Eigen/Dense>

#include "dynamics/kinematics.hpp"

namespace gaitopt::sim {
namespace {

/// The knots of one phase, as a trajectory of its own (no switch inside).
gaits::Trajectory phasePart(const gaits::Trajectory& step, gaits::Phase phase) {
  std::vector<gaits::Knot> knots;
  for (const auto& k : step.knots())
    if (k.phase == phase) knots.push_back(k);
  return gaits::Trajectory(step.robot(), step.stepLength(), std::move(knots));
}

void checkOptions(const ReferenceOptions& o) {
  if (!(o.strike_velocity >= 0 && std::isfinite(o.strike_velocity)))
    throw std::invalid_argument("reference strike velocity must be finite and >= 0 [m/s]");
  if (!(o.fade > 0 && std::isfinite(o.fade)))
    throw std::invalid_argument("reference fade time must be finite and > 0 [s]");
  if (!(o.fade_angle >= 0 && o.fade_rate >= 0 && std::isfinite(o.fade_angle) &&
        std::isfinite(o.fade_rate)))
    throw std::invalid_argument("reference fade bounds must be finite and >= 0");
  if (!(o.strike_window > 0 && std::isfinite(o.strike_window)))
    throw std::invalid_argument("reference strike window must be finite and > 0 [s]");
}

/// The change of the touchdown rates that raises the swing tip's downward speed to `strike`: the
/// least-norm change of the swing leg's link rates (the last legLinks() links, Mu Fig. 2.1),
/// keeping its forward speed where the swing leg has two links or more.
VecD strikeChange(const dynamics::Model& model, const gaits::Knot& touchdown, double strike) {
  VecD rates = VecD::Zero(model.nLinks());
  const Vec2d tip_velocity =
      dynamics::pointVelocity<double>(model.tipWeights(), touchdown.theta, VecD(touchdown.dtheta));
  const double dv = -strike - tip_velocity(1);
  if (dv >= 0) return rates;  // already descending fast enough
  const int k = model.legLinks(), first = model.nLinks() - k;
  const Eigen::MatrixXd jac =
      dynamics::pointJacobian<double>(model.tipWeights(), touchdown.theta).rightCols(k);
  const Eigen::MatrixXd rows = k >= 2 ? jac : Eigen::MatrixXd(jac.bottomRows(1));
  const Eigen::VectorXd want = k >= 2 ? Eigen::Vector2d(0, dv) : Eigen::VectorXd::Constant(1, dv);
  rates.segment(first, k) += rows.transpose() * (rows * rows.transpose()).ldlt().solve(want);
  return rates;
}

/// phi, phidot, phiddot of the strike phase-in at `late` seconds past the window's start.
struct StrikePhase {
  double phi, dphi, ddphi;
};
StrikePhase strikePhase(double late, double window) {
  if (late <= 0) return {0, 0, 0};
  if (late >= window) return {window / 2 + (late - window), 1, 0};
  const double s = late / window;
  return {window * (s * s * s - s * s * s * s / 2), 3 * s * s - 2 * s * s * s,
          (6 * s - 6 * s * s) / window};
}

/// Past touchdown the touchdown accelerations fade out over this time instead of dropping to
/// zero at once. A gait landing at rest brakes its swing leg hard into touchdown (190-270
/// rad/s^2 on the shipped optimum), and that braking holds the stance tip on the ground while
/// the body falls onto the front leg: dropped at once, the stance tip's normal force went from
/// +250 N to -241 N on a robot 5 % lighter than its model, one step of the clock after the
/// planned touchdown. Kept on, the braking would lift the swing tip again: the fade is short [s].
constexpr double kAccelerationFade = 0.02;

/// a(s) = (1 - s)^2 for s = late / w in [0, 1], zero after, and its first and second time
/// integrals per unit touchdown acceleration.
struct AccelerationFade {
  double x, v, a;
};
AccelerationFade accelerationFade(double late, double w) {
  const double s = std::min(late / w, 1.0), r = 1 - s;
  const double g1 = (1 - r * r * r) / 3, g2 = (s - (1 - r * r * r * r) / 4) / 3;
  return {w * w * g2 + w * g1 * std::max(late - w, 0.0), w * g1, r * r};
}

/// The touchdown knot `late` seconds on, before the strike: at the touchdown rates, with the
/// touchdown accelerations faded out (kAccelerationFade).
gaits::Knot pastTouchdown(gaits::Knot k, double late) {
  const AccelerationFade f = accelerationFade(late, kAccelerationFade);
  k.theta += k.dtheta * late + k.ddtheta * f.x;
  k.dtheta += k.ddtheta * f.v;
  k.ddtheta *= f.a;
  return k;
}

/// Cubic Hermite fade of the phase-start offset and its first two derivatives at s in [0, 1].
struct Fade {
  double h00, h10, dh00, dh10, ddh00, ddh10;
};
Fade fadeAt(double s) {
  return {2 * s * s * s - 3 * s * s + 1,
          s * s * s - 2 * s * s + s,
          6 * s * s - 6 * s,
          3 * s * s - 4 * s + 1,
          12 * s - 6,
          6 * s - 4};
}

}  // namespace

Reference::Reference(const gaits::Trajectory& step, ReferenceOptions options) : options_(options) {
  checkOptions(options);
  if (step.knots().size() < 2 || step.knots().front().phase != gaits::Phase::kSsp)
    throw std::invalid_argument(
        fmt::format("a reference step starts with single support and has at least 2 samples "
                    "(this one: {})",
                    step.knots().size()));
  ssp_ = phasePart(step, gaits::Phase::kSsp);
  ssp_end_ = ssp_.endTime();
  end_ = step.endTime();
  const auto dsp_count = std::count_if(step.knots().begin(), step.knots().end(),
                                       [](const auto& k) { return k.phase == gaits::Phase::kDsp; });
  if (dsp_count >= 2) dsp_ = phasePart(step, gaits::Phase::kDsp);
  strike_change_ = VecD::Zero(ssp_.nLinks());
}

Reference::Reference(const gaits::Trajectory& step, const dynamics::Model& model,
                     ReferenceOptions options)
    : Reference(step, options) {
  // Sized where the phase-in ends: the accelerations' fade and the posture have moved on.
  strike_change_ = strikeChange(model, pastTouchdown(ssp_.knots().back(), options.strike_window),
                                options.strike_velocity);
  hip_ = model.hipWeights();
  if (dsp_)
    for (const auto& k : dsp_->knots())
      dsp_hip_x_.push_back(dynamics::pointPosition<double>(*hip_, VecD(k.theta))(0));
}

double Reference::dspClockAt(const VecD& theta) const {
  if (!hip_ || !dsp_) return ssp_end_;
  const double x = dynamics::pointPosition<double>(*hip_, theta)(0);
  const auto& knots = dsp_->knots();
  double clock = knots.back().t;
  for (std::size_t i = 1; i < knots.size(); ++i) {
    const double x0 = dsp_hip_x_[i - 1], x1 = dsp_hip_x_[i];
    if (x1 < x) continue;
    const double w = x1 > x0 ? std::clamp((x - x0) / (x1 - x0), 0.0, 1.0) : 0.0;
    clock = knots[i - 1].t + w * (knots[i].t - knots[i - 1].t);
    break;
  }
  return std::clamp(clock, ssp_end_, ssp_end_ + 0.75 * (end_ - ssp_end_));
}

gaits::Knot Reference::singleSupport(double t) const {
  gaits::Knot k;
  if (t <= ssp_end_) {
    k = ssp_.at(std::max(t, ssp_.startTime()));
  } else {
    k = pastTouchdown(ssp_.knots().back(), t - ssp_end_);
  }
  const StrikePhase p = strikePhase(t - ssp_end_, options_.strike_window);
  k.theta += p.phi * strike_change_;
  k.dtheta += p.dphi * strike_change_;
  k.ddtheta += p.ddphi * strike_change_;
  return k;
}

gaits::Knot Reference::at(gaits::Phase phase, double t) const {
  gaits::Knot k = phase == gaits::Phase::kDsp && dsp_
                      ? dsp_->at(std::clamp(t, dsp_->startTime(), dsp_->endTime()))
                      : singleSupport(t);
  k.t = t;
  return k;
}

gaits::Knot Reference::at(gaits::Phase phase, double t, const PhaseStart& start) const {
  gaits::Knot k = at(phase, t);
  const double s = start.fade > 0 ? (t - start.t0) / start.fade : 1;
  if (s >= 1 || s < 0) return k;
  const Fade f = fadeAt(s);
  const double fd = start.fade;
  k.theta += f.h00 * start.d_theta + fd * f.h10 * start.d_dtheta;
  k.dtheta += f.dh00 / fd * start.d_theta + f.dh10 * start.d_dtheta;
  k.ddtheta += f.ddh00 / (fd * fd) * start.d_theta + f.ddh10 / fd * start.d_dtheta;
  return k;
}

PhaseStart Reference::startFrom(gaits::Phase phase, double t0, const VecD& theta,
                                const VecD& dtheta) const {
  const gaits::Knot k = at(phase, t0);
  const double phase_length = phase == gaits::Phase::kDsp ? end_ - t0 : ssp_end_;
  const auto clip = [](const VecD& v, double bound) -> VecD {
    return v.cwiseMax(-bound).cwiseMin(bound);
  };
  return {t0, std::min(options_.fade, phase_length),
          clip(theta - VecD(k.theta), options_.fade_angle),
          clip(dtheta - VecD(k.dtheta), options_.fade_rate)};
}

}  // namespace gaitopt::sim
