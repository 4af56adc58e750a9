#include "gaits/export/metrics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>

#include <fmt/format.h>

#include "dynamics/centre_of_pressure.hpp"
#include "dynamics/energy.hpp"
#include "dynamics/ground.hpp"
#include "dynamics/impact/impact.hpp"
#include "dynamics/joint_coordinates.hpp"

namespace gaitopt::gaits {
namespace {

/// Trapezoidal rule over consecutive knots. A switch pair has zero width, so it adds nothing and
/// the integrand may jump there: each integral runs phase by phase.
template <class F>
double trapezoid(const Trajectory& traj, F integrand) {
  const auto& knots = traj.knots();
  double sum = 0;
  for (size_t k = 0; k + 1 < knots.size(); ++k)
    sum += 0.5 * (integrand(knots[k]) + integrand(knots[k + 1])) * (knots[k + 1].t - knots[k].t);
  return sum;
}

/// Joint rates dq = M dtheta (Mu 2.41): torques tau are work-conjugate to q, not theta.
Eigen::VectorXd jointRates(const Knot& knot) {
  return dynamics::toJoint(VecD(knot.dtheta));
}

/// Vertical forces of the tips in contact: B always, E only in the DSP (E is in the air in the
/// SSP, whatever its stored force says).
template <class F>
void forEachContact(const Knot& knot, F visit) {
  visit(knot.force_stance);
  if (knot.phase == Phase::kDsp) visit(knot.force_swing);
}

void requireSameRobot(const Trajectory& traj, const dynamics::Model& model) {
  if (traj.nLinks() != model.nLinks())
    throw std::invalid_argument(fmt::format("trajectory has {} links but robot '{}' has {}",
                                            traj.nLinks(), model.name(), model.nLinks()));
}

/// Index of the last SSP knot before the first DSP knot: the pre-impact state at touchdown.
std::optional<size_t> touchdownKnot(const Trajectory& traj) {
  const auto& knots = traj.knots();
  for (size_t k = 1; k < knots.size(); ++k)
    if (knots[k].phase == Phase::kDsp && knots[k - 1].phase == Phase::kSsp) return k - 1;
  return std::nullopt;
}

/// Signed distance of x to the nearest end of [lo, hi], positive inside. An undefined ZMP (no
/// vertical force) counts as unsupported.
double margin(double x, double lo, double hi) {
  if (!std::isfinite(x)) return -kInfinity;
  return std::min(x - lo, hi - x);
}

}  // namespace

double absoluteWork(const Trajectory& traj) {
  return trapezoid(
      traj, [](const Knot& k) { return (k.tau.array() * jointRates(k).array()).abs().sum(); });
}

double torqueSquaredIntegral(const Trajectory& traj) {
  return trapezoid(traj, [](const Knot& k) { return k.tau.squaredNorm(); });
}

double costOfTransport(const Trajectory& traj, const dynamics::Model& model) {
  if (!(traj.stepLength() > 0))
    throw std::invalid_argument(
        fmt::format("cost of transport needs a positive step length, got {} m", traj.stepLength()));
  // W / (m g d) with |g| and d the distance along the ground, also on a slope (no cos gamma).
  return absoluteWork(traj) / (model.totalMass() * model.gravity() * traj.stepLength());
}

Eigen::VectorXd peakTorque(const Trajectory& traj) {
  Eigen::VectorXd peak = Eigen::VectorXd::Zero(traj.nLinks());
  for (const Knot& k : traj.knots()) peak = peak.cwiseMax(k.tau.cwiseAbs());
  return peak;
}

double minNormalForce(const Trajectory& traj) {
  double lowest = kInfinity;
  for (const Knot& k : traj.knots())
    forEachContact(k, [&](const Eigen::Vector2d& f) { lowest = std::min(lowest, f.y()); });
  return lowest;
}

Posture posture(const Trajectory& traj, const dynamics::Model& model) {
  Posture p;
  const int n = model.nLinks();
  const bool knees = model.legLinks() == 2;
  for (const Knot& k : traj.knots()) {
    if (model.torso()) p.torso_lean = std::max(p.torso_lean, std::abs(k.theta(*model.torso())));
    if (!knees) continue;
    p.stance_knee = std::max(p.stance_knee, std::abs(k.theta(1) - k.theta(0)));
    p.swing_knee = std::max(p.swing_knee, std::abs(k.theta(n - 2) - k.theta(n - 1)));
  }
  return p;
}

double maxFrictionRatio(const Trajectory& traj) {
  double highest = 0;
  for (const Knot& k : traj.knots())
    forEachContact(k, [&](const Eigen::Vector2d& f) {
      // A tip that pulls on the ground (or just touches it) needs infinite friction.
      highest = std::max(highest, f.y() > 0 ? std::abs(f.x()) / f.y() : kInfinity);
    });
  return highest;
}

double zmpX(const Knot& knot, double step_length) {
  const bool dsp = knot.phase == Phase::kDsp;
  const Vec2d force_e = dsp ? Vec2d(knot.force_swing) : Vec2d::Zero();
  const double x_e = dsp ? step_length : 0.0;
  // The ground moment on the robot at B is -tau0 (conventions.hpp).
  return dynamics::centreOfPressure<double>(0.0, knot.force_stance, -knot.tau(0), x_e, force_e);
}

double minZmpMargin(const Trajectory& traj, const dynamics::Model& model) {
  const dynamics::Foot& foot = model.foot();
  double lowest = kInfinity;
  for (const Knot& k : traj.knots()) {
    const double reach = k.phase == Phase::kDsp ? traj.stepLength() : 0.0;  // support ends at E
    lowest = std::min(lowest, margin(zmpX(k, traj.stepLength()), -foot.heel, reach + foot.toe));
  }
  return lowest;
}

std::optional<TouchdownImpact> touchdownImpact(const Trajectory& traj,
                                               const dynamics::Model& model) {
  requireSameRobot(traj, model);
  const auto& knots = traj.knots();
  const auto k = touchdownKnot(traj);
  // An SSP-only step ends at its strike: a single impact (no DSP follows).
  if (!k && (knots.empty() || knots.back().phase != Phase::kSsp)) return std::nullopt;
  TouchdownImpact t;
  t.knot = k ? *k : knots.size() - 1;
  t.double_impact = k.has_value();
  const Knot& pre = knots[t.knot];
  t.theta = pre.theta;
  t.dtheta_minus = pre.dtheta;
  const auto impact = t.double_impact ? dynamics::doubleImpact(model, t.theta, t.dtheta_minus)
                                      : dynamics::singleImpact(model, t.theta, t.dtheta_minus);
  t.dtheta_plus = impact.dtheta_plus;
  t.trailing_velocity = impact.trailing_velocity;
  return t;
}

double touchdownVelocityJump(const Trajectory& traj, const dynamics::Model& model) {
  const auto t = touchdownImpact(traj, model);
  return t ? (t->dtheta_plus - t->dtheta_minus).norm() : 0.0;
}

double impactEnergyLoss(const Trajectory& traj, const dynamics::Model& model) {
  const auto t = touchdownImpact(traj, model);
  if (!t) return 0.0;
  // After a single impact B moves (Mu 2.36b): its velocity carries kinetic energy too.
  return dynamics::kineticEnergy<double>(model, t->theta, t->dtheta_minus) -
         dynamics::kineticEnergy<double>(model, t->theta, t->dtheta_plus, t->trailing_velocity);
}

}  // namespace gaitopt::gaits
