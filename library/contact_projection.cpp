#include "library/contact_projection.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include <fmt/format.h>

#include "dynamics/impact/relabel.hpp"
#include "dynamics/kinematics.hpp"

namespace gaitopt::library {
namespace {

using gaits::Knot;
using gaits::Phase;

/// The least-norm change that removes `residual` through the tip's Jacobian: J^T (J J^T)^-1 r.
VecD leastChange(const Mat2X<double>& jac, const Vec2d& residual) {
  return jac.transpose() * (jac * jac.transpose()).ldlt().solve(residual);
}

/// The posture nearest `theta` (Gauss-Newton) with the swing tip at (step_length, 0).
VecD pinnedPosture(const dynamics::Model& model, VecD theta, double step_length) {
  const Vec2d target(step_length, 0.0);
  for (int iteration = 0; iteration < 20; ++iteration) {
    const Vec2d residual = target - dynamics::swingTip<double>(model, theta);
    if (residual.norm() < 1e-13 * std::max(1.0, step_length)) return theta;
    theta += leastChange(dynamics::pointJacobian<double>(model.tipWeights(), theta), residual);
  }
  throw std::runtime_error(fmt::format(
      "the blended posture cannot be brought onto a step of {:g} m: its swing tip does not reach",
      step_length));
}

/// A double-support knot on the pinned chain: posture, then rates and accelerations.
void pinKnot(const dynamics::Model& model, Knot& k, double step_length) {
  k.theta = pinnedPosture(model, k.theta, step_length);
  const Mat2X<double> jac = dynamics::pointJacobian<double>(model.tipWeights(), VecD(k.theta));
  k.dtheta -= leastChange(jac, jac * k.dtheta);
  const Vec2d bias = dynamics::pointBias<double>(model.tipWeights(), VecD(k.theta), VecD(k.dtheta));
  k.ddtheta -= leastChange(jac, jac * k.ddtheta + bias);
}

/// An angle difference in (-pi, pi]: relabelling wraps the angles it returns.
VecD wrapped(const VecD& d) {
  VecD out = d;
  for (int i = 0; i < out.size(); ++i) out(i) = std::remainder(out(i), 2 * std::numbers::pi);
  return out;
}

/// The single support's changes of angles and rates at its start (s = 0) and end (s = 1).
struct Bend {
  VecD start_angle, start_rate, end_angle, end_rate;
};

/// theta += a0 + h01 (a1 - a0) + h10 T v0 + h11 T v1 in s = (t - t0) / T: the quintic Hermite
/// basis with zero second derivative at both ends; rates and accelerations follow.
void bend(Knot& k, const Bend& b, double t0, double duration) {
  const double s = (k.t - t0) / duration, s2 = s * s, s3 = s2 * s, s4 = s3 * s, s5 = s4 * s;
  const double h01 = 10 * s3 - 15 * s4 + 6 * s5, h10 = s - 6 * s3 + 8 * s4 - 3 * s5,
               h11 = -4 * s3 + 7 * s4 - 3 * s5;
  const double d01 = 30 * s2 - 60 * s3 + 30 * s4, d10 = 1 - 18 * s2 + 32 * s3 - 15 * s4,
               d11 = -12 * s2 + 28 * s3 - 15 * s4;
  const double dd01 = 60 * s - 180 * s2 + 120 * s3, dd10 = -36 * s + 96 * s2 - 60 * s3,
               dd11 = -24 * s + 84 * s2 - 60 * s3;
  const VecD v0 = duration * b.start_rate, v1 = duration * b.end_rate;
  const VecD rise = b.end_angle - b.start_angle;
  k.theta += b.start_angle + h01 * rise + h10 * v0 + h11 * v1;
  k.dtheta += (d01 * rise + d10 * v0 + d11 * v1) / duration;
  k.ddtheta += (dd01 * rise + dd10 * v0 + dd11 * v1) / (duration * duration);
}

}  // namespace

void holdBlendContacts(std::vector<Knot>& knots, const dynamics::Model& model, double step_length,
                       const Vec2d& touchdown_velocity) {
  std::size_t dsp = 0;  // the first double-support knot (knots.size() if none)
  while (dsp < knots.size() && knots[dsp].phase == Phase::kSsp) ++dsp;
  if (dsp == 0) throw std::invalid_argument("a step starts in its single support");
  for (std::size_t k = dsp; k < knots.size(); ++k) pinKnot(model, knots[k], step_length);
  const Knot& first = knots.front();
  const Knot& touchdown = knots[dsp - 1];
  const VecD zero = VecD::Zero(first.theta.size());
  const VecD landed = pinnedPosture(model, touchdown.theta, step_length);
  const Mat2X<double> jac = dynamics::pointJacobian<double>(model.tipWeights(), landed);
  Bend b{zero, zero, landed - VecD(touchdown.theta),
         leastChange(jac, touchdown_velocity - jac * VecD(touchdown.dtheta))};
  if (dsp < knots.size()) {  // periodic through the relabelling of the double support's end
    b.start_angle = wrapped(dynamics::relabelAngles<double>(model, VecD(knots.back().theta)) -
                            VecD(first.theta));
    b.start_rate = dynamics::relabelRates<double>(VecD(knots.back().dtheta)) - VecD(first.dtheta);
  }
  const double t0 = first.t, duration = touchdown.t - first.t;
  for (std::size_t k = 0; k < dsp; ++k) bend(knots[k], b, t0, duration);
}

}  // namespace gaitopt::library
