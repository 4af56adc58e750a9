#include "ocp/shape/phase_builder.hpp"

#include <algorithm>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <string>

#include "dynamics/joint_coordinates.hpp"
#include "ocp/problem/dsp_chart.hpp"
#include "ocp/problem/ground_contact.hpp"
#include "ocp/problem/interior_contact.hpp"
#include "ocp/problem/interior_work.hpp"
#include "ocp/problem/jerk_jump.hpp"
#include "ocp/problem/jerk_limit.hpp"
#include "ocp/problem/path_functions.hpp"
#include "ocp/problem/torque_rate_limit.hpp"
#include "ocp/transcription/biped_dynamics.hpp"

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

/// A free duration T is a variable of its own, ahead of the phase's points.
int addDuration(Nlp& nlp, const PhaseConfig& config, const std::string& phase) {
  if (!config.freeDuration()) return -1;
  return nlp
      .addVariables(phase + "_duration", 1, Eigen::VectorXd::Constant(1, config.duration_min),
                    Eigen::VectorXd::Constant(1, config.duration_max),
                    Eigen::VectorXd::Constant(1, config.duration), phase)
      .offset;
}

void addPathConstraint(Nlp& nlp, const Phase& phase, const std::string& what,
                       std::shared_ptr<const PointFunction> f) {
  nlp.addConstraint(std::make_unique<PathConstraint>(phase.name() + "_" + what, phase.name(),
                                                     phase.layout, std::move(f)));
}

/// The weighted running costs: torque squared, and absolute work through slacks, alone or
/// per weight and step length (cost of transport, W / (m g d)).
void addPhaseCost(Nlp& nlp, const dynamics::Model& model, const OcpConfig& c, const Phase& phase) {
  if (c.cost.torque_squared > 0)
    nlp.addCost(std::make_unique<QuadratureCost>(
        phase.name() + "_torque_squared", phase.layout,
        std::make_shared<TorqueSquared>(phase.point, c.cost.torque_squared)));
  if (!phase.point.hasWorkSlacks()) return;
  addPathConstraint(nlp, phase, "work_split", std::make_shared<WorkSplit>(phase.point));
  const double weight = c.cost.abs_work + c.cost.cost_of_transport /
                                              (model.totalMass() * model.gravity() * c.step_length);
  // Hermite-Simpson: the work is also split inside the segments (interior_work.hpp), so it holds
  // between the points; the points then carry their share of the composite Simpson rule.
  const bool interior = phase.layout.scheme == Scheme::kHermiteSimpson;
  nlp.addCost(std::make_unique<QuadratureCost>(
      phase.name() + "_abs_work", phase.layout, std::make_shared<AbsoluteWork>(phase.point, weight),
      interior ? pointWeights(phase.layout) : Eigen::VectorXd()));
  if (interior) addInteriorWork(nlp, phase, weight);
}

}  // namespace

Phase addPhaseVariables(Nlp& nlp, const dynamics::Model& model, const OcpConfig& c,
                        const gaits::Trajectory& guess, const PhaseSpec& spec,
                        std::optional<int> shared_duration) {
  const int n = model.nLinks();
  Phase phase;
  phase.kind = spec.kind;
  phase.label = spec.label;
  phase.reduced_coordinates = phase.doubleSupport() && c.dsp_reduced_coordinates;
  // Work slacks only where the work is a cost: elsewhere nothing would tie them down.
  phase.point = PointLayout::biped(n, phase.doubleSupport(), spec.cost && c.cost.needsWorkSlacks());
  phase.layout = PhaseLayout{.scheme = c.scheme,
                             .segments = spec.mesh.segments,
                             .duration = spec.mesh.duration,
                             .nx = phase.point.stateSize(),
                             .nu = phase.point.u.size,
                             .nz = phase.point.algebraicSize(),
                             .nq = phase.point.q.size,
                             .mesh = spec.mesh.fractions()};
  PhaseLayout& l = phase.layout;
  l.validate();
  l.duration_index = shared_duration ? *shared_duration : addDuration(nlp, spec.mesh, phase.name());
  const auto [lo, hi] = pointBounds(model, c, phase.point);
  Eigen::VectorXd x0(l.variables());
  for (int k = 0; k < l.points(); ++k)
    x0.segment(l.pointOffset(k) - l.offset, l.pointSize()) = guessPoint(guess, phase, l.time(k));
  l.offset = nlp.addVariables(phase.name() + "_points", l.variables(), lo.replicate(l.points(), 1),
                              hi.replicate(l.points(), 1), x0, phase.name(), l.pointSize())
                 .offset;
  return phase;
}

void addPhaseSets(Nlp& nlp, const dynamics::Model& model, const OcpConfig& c, const Phase& phase,
                  bool cost) {
  if (phase.reduced_coordinates)
    addReducedDsp(nlp, model, phase, c.step_length);
  else
    nlp.addConstraint(std::make_unique<CollocationDefects>(phase.name() + "_defects", phase.name(),
                                                           phase.layout));
  addPathConstraint(nlp, phase, "dynamics", std::make_shared<BipedDynamics>(model, phase.point));
  if (c.jerk_limit > 0)
    nlp.addConstraint(std::make_unique<JerkLimit>(phase.name() + "_jerk", phase, c.jerk_limit));
  if (c.torque_rate_limit > 0)
    nlp.addConstraint(std::make_unique<TorqueRateLimit>(phase.name() + "_torque_rate", phase,
                                                        c.torque_rate_limit));
  if (c.jerk_jump_limit > 0 && phase.layout.segments > 1)
    nlp.addConstraint(
        std::make_unique<JerkJump>(phase.name() + "_jerk_jump", phase, c.jerk_jump_limit));
  if (c.joint_velocity_limits)
    addPathConstraint(nlp, phase, "joint_rates",
                      std::make_shared<JointRateLimits>(model, phase.point));
  if (c.knee_limits && model.legLinks() == 2)
    addPathConstraint(nlp, phase, "knees",
                      std::make_shared<KneeDirection>(
                          phase.point, c.max_stance_knee_flexion, c.max_swing_knee_flexion,
                          phase.doubleSupport() ? c.min_trailing_knee_flexion : 0.0));
  else if (c.max_stance_knee_flexion < kInf || c.max_swing_knee_flexion < kInf ||
           c.min_trailing_knee_flexion > 0)
    throw std::invalid_argument(
        "constraints: a knee flexion bound, but the robot's legs have no knees");
  if (c.ground_contact) {
    // The ZMP rows only bound an ankle torque, so a passive ankle has none.
    const auto zmp_foot = c.zmp && model.joints().front().actuated
                              ? std::optional<dynamics::Foot>(marginFoot(model, c))
                              : std::nullopt;
    const auto contact = std::make_shared<const GroundContact>(
        model, phase.point, zmp_foot, c.step_length, frictionBound(model, c), c.min_normal_force);
    addPathConstraint(nlp, phase, "ground_contact", contact);
    if (c.interior_contact > 0 && !phase.doubleSupport())
      nlp.addConstraint(std::make_unique<InteriorContact>(phase.name() + "_interior_contact", phase,
                                                          contact, c.interior_contact));
  }
  if (!phase.doubleSupport() && c.clearance.enabled)
    nlp.addConstraint(std::make_unique<SwingClearance>(model, phase, c.clearance));
  if (cost) addPhaseCost(nlp, model, c, phase);
}

}  // namespace gaitopt::ocp
