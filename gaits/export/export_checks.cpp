#include "gaits/export/export_checks.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "dynamics/centre_of_pressure.hpp"
#include "dynamics/joint_coordinates.hpp"
#include "dynamics/kinematics.hpp"

namespace gaitopt::gaits {
namespace {

using KnotVector = Eigen::VectorXd Knot::*;

/// d f / dt at the middle of three samples (t0 < t1 < t2), exact for quadratics.
Eigen::VectorXd threePointDerivative(const Knot& a, const Knot& b, const Knot& c, KnotVector f) {
  const double h1 = b.t - a.t, h2 = c.t - b.t;
  return (h1 * h1 * (c.*f) - h2 * h2 * (a.*f) + (h2 * h2 - h1 * h1) * (b.*f)) /
         (h1 * h2 * (h1 + h2));
}

/// max_k |three-point derivative of f - df_k|_inf / max_k |df_k|_inf within phases.
double maxDerivativeMismatch(const Trajectory& traj, KnotVector f, KnotVector df) {
  const auto& knots = traj.knots();
  double worst = 0, scale = 0;
  for (const Knot& k : knots) scale = std::max(scale, (k.*df).cwiseAbs().maxCoeff());
  for (size_t i = 1; i + 1 < knots.size(); ++i) {
    const Knot &a = knots[i - 1], &b = knots[i], &c = knots[i + 1];
    if (a.phase != b.phase || c.phase != b.phase || !(a.t < b.t && b.t < c.t)) continue;
    worst = std::max(worst, (threePointDerivative(a, b, c, f) - b.*df).cwiseAbs().maxCoeff());
  }
  return scale > 0 ? worst / scale : worst;
}

}  // namespace

double minSwingClearance(const Trajectory& traj, const dynamics::Model& model) {
  double lowest = kInfinity;
  for (const Knot& k : traj.knots())
    if (k.phase == Phase::kSsp)
      lowest = std::min(lowest, dynamics::swingTip(model, VecD(k.theta)).y());
  return lowest;
}

namespace {

/// max over the knots and the joints with a limit (> 0) of |value_j| / limit_j.
template <class Value, class Limit>
double largestUse(const Trajectory& traj, const dynamics::Model& model, Value value, Limit limit) {
  double largest = 0;
  for (const Knot& k : traj.knots()) {
    const Eigen::VectorXd v = value(k);
    for (int j = 0; j < model.nLinks(); ++j)
      if (const double bound = limit(model.joints()[static_cast<std::size_t>(j)]); bound > 0)
        largest = std::max(largest, std::abs(v(j)) / bound);
  }
  return largest;
}

}  // namespace

double maxJointRateUse(const Trajectory& traj, const dynamics::Model& model) {
  return largestUse(
      traj, model, [](const Knot& k) { return dynamics::toJoint(VecD(k.dtheta)); },
      [](const dynamics::Joint& j) { return j.velocity_limit; });
}

double maxTorqueUse(const Trajectory& traj, const dynamics::Model& model) {
  return largestUse(
      traj, model, [](const Knot& k) { return VecD(k.tau); },
      [](const dynamics::Joint& j) { return j.actuated ? j.torque_limit : 0.0; });
}

double minFootCopMargin(const Trajectory& traj, const dynamics::Model& model) {
  const dynamics::Foot& foot = model.foot();
  double lowest = kInfinity;
  for (const Knot& k : traj.knots()) {
    const double normal = k.force_stance.y();
    if (!(normal > 0)) return -kInfinity;
    lowest = std::min(lowest, dynamics::copMargin(dynamics::stanceCop(k.tau(0), normal), foot));
  }
  return lowest;
}

double maxDspTipDrift(const Trajectory& traj, const dynamics::Model& model) {
  double worst = 0;
  const Vec2d pinned(traj.stepLength(), 0.0);
  for (const Knot& k : traj.knots())
    if (k.phase == Phase::kDsp)
      worst = std::max(worst, (dynamics::swingTip(model, VecD(k.theta)) - pinned).norm());
  return worst;
}

double maxRateMismatch(const Trajectory& traj) {
  return maxDerivativeMismatch(traj, &Knot::theta, &Knot::dtheta);
}

double maxAccelerationMismatch(const Trajectory& traj) {
  return maxDerivativeMismatch(traj, &Knot::dtheta, &Knot::ddtheta);
}

}  // namespace gaitopt::gaits
