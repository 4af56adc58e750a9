#include "library/interpolation.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "dynamics/ground.hpp"
#include "dynamics/kinematics.hpp"
#include "dynamics/ssp_dynamics.hpp"
#include "library/contact_projection.hpp"
#include "library/library_config.hpp"

namespace gaitopt::library {
namespace {

/// Bracketing positions along one axis and the weight of the upper one.
struct Bracket {
  int lo = 0, hi = 0;
  double w = 0;
};

Bracket bracket(const std::vector<double>& axis, double v, const std::string& name) {
  const double tol = 1e-9 * std::max(1.0, std::abs(v));
  if (v < axis.front() - tol || v > axis.back() + tol)
    throw std::domain_error(fmt::format("{} {:g} is outside the library's range [{:g}, {:g}]", name,
                                        v, axis.front(), axis.back()));
  // A query at a grid value within the tolerance is that value: a range's values (0.3 + 0.6 =
  // 0.8999999999999999) and the ones a user types (0.9) differ in the last bit, which would
  // blend in a neighbour at weight 1e-16 and refuse the point if that neighbour failed.
  for (std::size_t i = 0; i < axis.size(); ++i)
    if (std::abs(v - axis[i]) <= tol) return {static_cast<int>(i), static_cast<int>(i), 0.0};
  const auto it = std::upper_bound(axis.begin(), axis.end(), v);
  const int hi =
      std::clamp(static_cast<int>(it - axis.begin()), 1, static_cast<int>(axis.size()) - 1);
  const double a = axis[static_cast<std::size_t>(hi - 1)], b = axis[static_cast<std::size_t>(hi)];
  return {hi - 1, hi, std::clamp((v - a) / (b - a), 0.0, 1.0)};
}

/// One phase of one corner gait: its knots' time span.
struct PhaseSpan {
  double start = 0, duration = 0;
  std::size_t last_knot = 0;  ///< the phase's final knot (at() would give the next phase's)
};

std::vector<PhaseSpan> phaseSpans(const gaits::Trajectory& traj) {
  std::vector<PhaseSpan> spans;
  const auto& knots = traj.knots();
  for (std::size_t k = 0; k < knots.size(); ++k) {
    if (k == 0 || knots[k].phase != knots[k - 1].phase) spans.push_back({knots[k].t, 0, k});
    spans.back().duration = knots[k].t - spans.back().start;
    spans.back().last_knot = k;
  }
  return spans;
}

/// The corner's knot at phase fraction s, with rates as derivatives in s.
gaits::Knot normalisedKnot(const gaits::Trajectory& traj, const PhaseSpan& span, double s) {
  gaits::Knot k = s >= 1 ? traj.knots()[span.last_knot] : traj.at(span.start + s * span.duration);
  k.dtheta *= span.duration;
  k.ddtheta *= span.duration * span.duration;
  return k;
}

void accumulate(gaits::Knot& sum, const gaits::Knot& k, double w) {
  sum.theta += w * k.theta;
  sum.dtheta += w * k.dtheta;
  sum.ddtheta += w * k.ddtheta;
  sum.force_swing += w * k.force_swing;
}

/// Torques and the stance force made consistent with the blended motion and swing-tip force:
/// tau = M^-T (D ddtheta + N - J_E^T F_E) (Mu 2.11 with 2.43; F_E = 0 in the SSP), so the blend
/// misses the dynamics only where it must, in the pinned tip's acceleration.
void inverseDynamics(const dynamics::Model& model, gaits::Knot& k) {
  const VecD theta = k.theta, dtheta = k.dtheta, ddtheta = k.ddtheta;
  const VecD tip_load =
      dynamics::pointJacobian<double>(model.tipWeights(), theta).transpose() * k.force_swing;
  k.tau = dynamics::sspInverseDynamics(model, theta, dtheta, ddtheta) -
          dynamics::jointTorque<double>(tip_load);
  k.force_stance = dynamics::stanceForce<double>(model, theta, dtheta, ddtheta, k.force_swing);
}

struct Corner {
  const gaits::Trajectory* traj;
  std::vector<PhaseSpan> spans;
  double weight;
};

std::vector<Corner> corners(const Grid& grid, const GaitLookup& gait_at,
                            const std::vector<double>& values) {
  std::vector<Corner> out;
  for (const auto& [p, w] : cellWeights(grid, values)) {
    const gaits::Trajectory* traj = gait_at(p);
    if (traj == nullptr)
      throw std::domain_error(
          fmt::format("the library has no solved gait at {}, a corner of "
                      "the cell holding the query",
                      grid.point(p).name));
    out.push_back({traj, phaseSpans(*traj), w});
    if (out.back().spans.size() != out.front().spans.size())
      throw std::invalid_argument("library gaits with different phases cannot be blended");
  }
  return out;
}

}  // namespace

std::vector<std::pair<int, double>> cellWeights(const Grid& grid,
                                                const std::vector<double>& values) {
  const int n = grid.dimensions();
  if (static_cast<int>(values.size()) != n)
    throw std::invalid_argument(
        fmt::format("a library query needs {} values (one per axis), got {}", n, values.size()));
  std::vector<Bracket> b;
  for (int a = 0; a < n; ++a) b.push_back(bracket(grid.axes()[a], values[a], grid.axisName(a)));
  std::vector<std::pair<int, double>> out;
  for (int mask = 0; mask < (1 << n); ++mask) {
    std::vector<double> at(static_cast<std::size_t>(n));
    double w = 1;
    for (int a = 0; a < n; ++a) {
      const bool upper = (mask >> a) & 1;
      at[a] = grid.axes()[a][static_cast<std::size_t>(upper ? b[a].hi : b[a].lo)];
      w *= upper ? b[a].w : 1 - b[a].w;
    }
    if (w > 0) out.emplace_back(grid.nearest(at), w);
  }
  return out;
}

namespace {

/// The blended knot at phase fraction s of phase `ph` lasting `duration` from t0 (its motion
/// and swing-tip force: torques and stance force are set later).
gaits::Knot blendedKnot(const std::vector<Corner>& cs, std::size_t ph, double s, double t0,
                        double duration) {
  gaits::Knot k = normalisedKnot(*cs.front().traj, cs.front().spans[ph], s);
  k.theta.setZero();
  k.dtheta.setZero();
  k.ddtheta.setZero();
  k.force_swing.setZero();
  for (const auto& c : cs) accumulate(k, normalisedKnot(*c.traj, c.spans[ph], s), c.weight);
  k.t = t0 + s * duration;
  k.dtheta /= duration;
  k.ddtheta /= duration * duration;
  return k;
}

/// The corners' swing-tip velocity at the end of their single support, weighted [m/s].
Vec2d touchdownVelocity(const std::vector<Corner>& cs, const dynamics::Model& model) {
  Vec2d v = Vec2d::Zero();
  for (const auto& c : cs) {
    const gaits::Knot& k = c.traj->knots()[c.spans.front().last_knot];
    v += c.weight *
         dynamics::pointVelocity<double>(model.tipWeights(), VecD(k.theta), VecD(k.dtheta));
  }
  return v;
}

}  // namespace

// The knots lie on the step's grid j / rate_hz, with both ends of each phase, as an optimum's
// dense export (ocp/problem/gait_problem.cpp): the written trajectory.csv is then these knots,
// not a re-interpolation of them, whose torques would miss the inverse dynamics of the
// interpolated motion between them.
gaits::Trajectory interpolateGait(const Grid& grid, const GaitLookup& gait_at,
                                  const dynamics::Model& model, const std::vector<double>& values,
                                  double rate_hz) {
  if (!(rate_hz > 0)) throw std::invalid_argument("the sample rate must be positive");
  const std::vector<Corner> cs = corners(grid, gait_at, values);
  const double step_time = values[kStepLength] / values[kSpeed];
  double corner_time = 0;  // the corners' weighted step time gives the phases' split
  for (const auto& c : cs) corner_time += c.weight * c.traj->duration();
  const double gap = 1e-3 / rate_hz;  // no sliver next to a phase's end
  std::vector<gaits::Knot> knots;
  double t0 = 0;
  for (std::size_t ph = 0; ph < cs.front().spans.size(); ++ph) {
    double fraction = 0;
    for (const auto& c : cs) fraction += c.weight * c.spans[ph].duration / corner_time;
    const double duration = fraction * step_time;
    knots.push_back(blendedKnot(cs, ph, 0.0, t0, duration));
    for (auto j = static_cast<long>(std::floor(t0 * rate_hz)) + 1;; ++j) {
      const double t = static_cast<double>(j) / rate_hz;
      if (t > t0 + duration - gap) break;
      if (t <= t0 + gap) continue;
      knots.push_back(blendedKnot(cs, ph, (t - t0) / duration, t0, duration));
      knots.back().t = t;  // exactly on the grid, not an ulp off it
    }
    knots.push_back(blendedKnot(cs, ph, 1.0, t0, duration));
    t0 += duration;
  }
  holdBlendContacts(knots, model, values[kStepLength], touchdownVelocity(cs, model));
  for (gaits::Knot& k : knots) inverseDynamics(model, k);
  return gaits::Trajectory(cs.front().traj->robot(), values[kStepLength], std::move(knots));
}

}  // namespace gaitopt::library
