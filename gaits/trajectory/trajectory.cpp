#include "gaits/trajectory/trajectory.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <utility>

#include <fmt/format.h>

namespace gaitopt::gaits {
namespace {

// ---------------------------------------------------------------------------------------------
// Validation (constructor)

void requireSize(const Eigen::VectorXd& v, int n, size_t k, const char* field) {
  if (v.size() != n)
    throw std::invalid_argument(
        fmt::format("knot {}: {} has {} entries, expected {} (the size of theta in knot 0)", k,
                    field, v.size(), n));
}

void requireFinite(const Eigen::VectorXd& v, size_t k, const char* field) {
  for (Eigen::Index i = 0; i < v.size(); ++i)
    if (!std::isfinite(v(i)))
      throw std::invalid_argument(
          fmt::format("knot {}: {}[{}] is {}, expected a finite number", k, field, i, v(i)));
}

void checkKnot(const Knot& knot, int n, size_t k) {
  if (!std::isfinite(knot.t))
    throw std::invalid_argument(fmt::format("knot {}: time is {}, expected finite", k, knot.t));
  requireSize(knot.theta, n, k, "theta");
  requireSize(knot.dtheta, n, k, "dtheta");
  requireSize(knot.ddtheta, n, k, "ddtheta");
  requireSize(knot.tau, n, k, "tau");
  requireFinite(knot.theta, k, "theta");
  requireFinite(knot.dtheta, k, "dtheta");
  requireFinite(knot.ddtheta, k, "ddtheta");
  requireFinite(knot.tau, k, "tau");
  requireFinite(knot.force_stance, k, "force_stance");
  requireFinite(knot.force_swing, k, "force_swing");
}

/// Knots k and k+1: time must not decrease, and the phase may change only at a switch pair
/// (SSP knot then DSP knot at the same time), the one place where rates and forces may jump.
void checkOrder(const Knot& a, const Knot& b, size_t k) {
  if (b.t < a.t)
    throw std::invalid_argument(
        fmt::format("knot {}: time {} is before knot {}'s {}; knots must be sorted by time", k + 1,
                    b.t, k, a.t));
  if (b.t == a.t && !(a.phase == Phase::kSsp && b.phase == Phase::kDsp))
    throw std::invalid_argument(fmt::format(
        "knots {} and {} share the time {} but are {} -> {}; the only same-time pair allowed is "
        "a phase switch SSP -> DSP",
        k, k + 1, a.t, toString(a.phase), toString(b.phase)));
  if (b.t > a.t && a.phase != b.phase)
    throw std::invalid_argument(fmt::format(
        "knots {} and {} change phase {} -> {} between t = {} and t = {}; a phase switch must be "
        "stored as two knots at the same time (last SSP knot, first DSP knot)",
        k, k + 1, toString(a.phase), toString(b.phase), a.t, b.t));
}

// ---------------------------------------------------------------------------------------------
// Interpolation (at)

/// The quintic p(s) = c0 + c1 s + ... + c5 s^5 in the local time s = t - t_k that matches
/// theta, dtheta and ddtheta at both ends of a segment of length h > 0 (Hermite data), one
/// column of coefficients per link. Exact for any quintic, error O(h^6) otherwise.
class QuinticSegment {
 public:
  QuinticSegment(const Knot& a, const Knot& b) {
    const double h = b.t - a.t;
    // Remainders at s = h after the Taylor part c0 + c1 s + c2 s^2 fixed by knot a.
    const Eigen::ArrayXd dp = (b.theta - a.theta - h * a.dtheta - 0.5 * h * h * a.ddtheta).array();
    const Eigen::ArrayXd dv = (b.dtheta - a.dtheta - h * a.ddtheta).array();
    const Eigen::ArrayXd da = (b.ddtheta - a.ddtheta).array();
    c_[0] = a.theta.array();
    c_[1] = a.dtheta.array();
    c_[2] = 0.5 * a.ddtheta.array();
    // Solution of the 3x3 end-condition system for c3, c4, c5.
    c_[3] = (10 * dp - 4 * h * dv + 0.5 * h * h * da) / std::pow(h, 3);
    c_[4] = (-15 * dp + 7 * h * dv - h * h * da) / std::pow(h, 4);
    c_[5] = (6 * dp - 3 * h * dv + 0.5 * h * h * da) / std::pow(h, 5);
  }

  Eigen::VectorXd value(double s) const {
    return c_[0] + s * (c_[1] + s * (c_[2] + s * (c_[3] + s * (c_[4] + s * c_[5]))));
  }
  Eigen::VectorXd rate(double s) const {
    return c_[1] + s * (2 * c_[2] + s * (3 * c_[3] + s * (4 * c_[4] + s * 5 * c_[5])));
  }
  Eigen::VectorXd acceleration(double s) const {
    return 2 * c_[2] + s * (6 * c_[3] + s * (12 * c_[4] + s * 20 * c_[5]));
  }

 private:
  Eigen::ArrayXd c_[6];
};

/// State at t strictly inside the segment [a.t, b.t) of positive length.
Knot interpolate(const Knot& a, const Knot& b, double t) {
  const QuinticSegment quintic(a, b);
  const double s = t - a.t;
  const double w = s / (b.t - a.t);  // linear weight of knot b
  Knot out;
  out.t = t;
  out.phase = a.phase;  // a and b share the phase: switches are same-time pairs
  out.theta = quintic.value(s);
  out.dtheta = quintic.rate(s);
  out.ddtheta = quintic.acceleration(s);
  out.tau = (1 - w) * a.tau + w * b.tau;
  out.force_stance = (1 - w) * a.force_stance + w * b.force_stance;
  out.force_swing = (1 - w) * a.force_swing + w * b.force_swing;
  return out;
}

// ---------------------------------------------------------------------------------------------
// Resampling

/// start + k / rate for k = 0, 1, ... strictly before the end (less the tolerance), then the end
/// itself, so the last sample is exactly the final knot.
std::vector<double> gridTimes(double start, double end, double rate_hz) {
  std::vector<double> times;
  for (size_t k = 0;; ++k) {
    const double t = start + static_cast<double>(k) / rate_hz;
    if (t >= end - kTimeTolerance) break;
    times.push_back(t);
  }
  times.push_back(end);
  return times;
}

/// Index of the SSP knot of every switch pair.
std::vector<size_t> switchIndices(const std::vector<Knot>& knots) {
  std::vector<size_t> out;
  for (size_t k = 0; k + 1 < knots.size(); ++k)
    if (knots[k].t == knots[k + 1].t) out.push_back(k);
  return out;
}

}  // namespace

const char* toString(Phase phase) {
  switch (phase) {
    case Phase::kSsp:
      return "SSP";
    case Phase::kDsp:
      return "DSP";
  }
  return "?";
}

Phase phaseFromString(const std::string& text) {
  if (text == "SSP") return Phase::kSsp;
  if (text == "DSP") return Phase::kDsp;
  throw std::invalid_argument(fmt::format("unknown phase '{}', expected SSP or DSP", text));
}

Trajectory::Trajectory(std::string robot, double step_length, std::vector<Knot> knots)
    : robot_(std::move(robot)), step_length_(step_length), knots_(std::move(knots)) {
  if (!std::isfinite(step_length_))
    throw std::invalid_argument(fmt::format("step length is {}, expected finite", step_length_));
  if (knots_.empty()) throw std::invalid_argument("a trajectory needs at least one knot");
  // The dynamics work in fixed-capacity vectors (conventions.hpp), so bound n here once.
  const auto n = static_cast<int>(knots_.front().theta.size());
  if (n < 1 || n > kMaxLinks)
    throw std::invalid_argument(
        fmt::format("knot 0: theta has {} entries, expected 1 to {} links", n, kMaxLinks));
  for (size_t k = 0; k < knots_.size(); ++k) {
    checkKnot(knots_[k], n, k);
    if (k > 0) checkOrder(knots_[k - 1], knots_[k], k - 1);
  }
}

int Trajectory::nLinks() const {
  return knots_.empty() ? 0 : static_cast<int>(knots_.front().theta.size());
}

// An empty (default-constructed) trajectory spans [0, 0]; at() still throws for it.
double Trajectory::startTime() const {
  return knots_.empty() ? 0.0 : knots_.front().t;
}
double Trajectory::endTime() const {
  return knots_.empty() ? 0.0 : knots_.back().t;
}

std::vector<std::pair<Phase, double>> Trajectory::phaseDurations() const {
  std::vector<std::pair<Phase, double>> out;
  size_t first = 0;
  for (size_t k = 1; k <= knots_.size(); ++k) {
    if (k < knots_.size() && knots_[k].phase == knots_[first].phase) continue;
    out.emplace_back(knots_[first].phase, knots_[k - 1].t - knots_[first].t);
    first = k;
  }
  return out;
}

Knot Trajectory::at(double t) const {
  if (knots_.empty() || !(t >= startTime() && t <= endTime()))
    throw std::out_of_range(
        fmt::format("trajectory evaluated at t = {}, outside [{}, {}]", t, startTime(), endTime()));
  if (t == endTime()) return knots_.back();
  // First knot strictly after t; the one before it starts the segment. At a switch time this
  // picks the DSP knot of the pair: evaluation is right-continuous.
  const auto after = std::upper_bound(knots_.begin(), knots_.end(), t,
                                      [](double time, const Knot& k) { return time < k.t; });
  const Knot& a = *(after - 1);
  if (t == a.t) return a;  // exact knot values, no rounding through the polynomial
  return interpolate(a, *after, t);
}

Trajectory Trajectory::resample(double rate_hz) const {
  if (!(std::isfinite(rate_hz) && rate_hz > 0))
    throw std::invalid_argument(fmt::format("resample rate is {} Hz, expected > 0", rate_hz));
  if (knots_.empty()) return *this;
  const std::vector<size_t> switches = switchIndices(knots_);
  std::vector<Knot> out;
  size_t next = 0;  // next switch pair to emit
  const auto switchTime = [&](size_t i) { return knots_[switches[i]].t; };
  const auto emitSwitch = [&] {
    out.push_back(knots_[switches[next]]);
    out.push_back(knots_[switches[next] + 1]);
    ++next;
  };
  const std::vector<double> grid = gridTimes(startTime(), endTime(), rate_hz);
  for (size_t i = 0; i < grid.size(); ++i) {
    const double t = grid[i];
    // Interior grid points near a switch would make a sliver segment or duplicate the DSP knot,
    // so the pair stands in for them; the endpoints are kept unless a switch is exactly there.
    const bool endpoint = i == 0 || i + 1 == grid.size();
    const double tolerance = endpoint ? 0.0 : kTimeTolerance;
    while (next < switches.size() && switchTime(next) < t - tolerance) emitSwitch();
    if (next < switches.size() && std::abs(switchTime(next) - t) <= tolerance) continue;
    out.push_back(at(t));
  }
  while (next < switches.size()) emitSwitch();
  return Trajectory(robot_, step_length_, std::move(out));
}

}  // namespace gaitopt::gaits
