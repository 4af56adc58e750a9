#include "sim/controllers/hzd_virtual_constraints.hpp"

#include <algorithm>
#include <stdexcept>

#include <fmt/format.h>

#include "dynamics/impact/impact.hpp"
#include "dynamics/impact/relabel.hpp"
#include "dynamics/joint_coordinates.hpp"

namespace gaitopt::sim {
namespace {

constexpr int kCheckSamples = 201;  // knots of the reference the fit is checked on
constexpr int kBisections = 60;     // time of a node's phase, to machine precision

/// The actuated joints q_1 .. q_n-1 of theta (or of its rates).
VecD actuated(const VecD& theta) {
  const VecD q = dynamics::toJoint<double>(theta);
  return q.tail(q.size() - 1);
}

/// d q_a / d phi along a motion with rates dtheta.
VecD slope(const VecD& c, const VecD& dtheta) {
  return actuated(dtheta) / c.dot(dtheta);
}

}  // namespace

ImpactImage hzdImpact(const dynamics::Model& model, const VecD& theta, const VecD& dtheta,
                      bool single) {
  const auto r = single ? dynamics::singleImpact(model, theta, dtheta)
                        : dynamics::doubleImpact(model, theta, dtheta);
  return {dynamics::relabelAngles<double>(model, theta),
          dynamics::relabelRates<double>(r.dtheta_plus)};
}

gaits::Knot VirtualConstraints::node(const dynamics::Model& model, const gaits::Knot& k) const {
  // d/dphi = (1/phidot) d/dt: q_a' = qdot_a / phidot, q_a'' = (qddot_a - q_a' phiddot) / phidot^2.
  const double rate = c_.dot(k.dtheta), acceleration = c_.dot(k.ddtheta);
  const VecD first = actuated(k.dtheta) / rate;
  return {phase(k.theta),
          gaits::Phase::kSsp,
          actuated(k.theta),
          first,
          (actuated(k.ddtheta) - first * acceleration) / (rate * rate),
          VecD::Zero(model.nLinks() - 1)};
}

VirtualConstraints::VirtualConstraints(const dynamics::Model& model, const Reference& ref,
                                       int nodes) {
  const int n = model.nLinks();
  if (nodes < 2) throw std::invalid_argument("HZD: the spline needs at least 2 nodes");
  for (int j = 1; j < n; ++j)
    if (!model.joints()[static_cast<std::size_t>(j)].actuated)
      throw std::invalid_argument(fmt::format(
          "HZD: joint '{}' is unactuated (virtual constraints need every joint but the stance "
          "ankle actuated)",
          model.joints()[static_cast<std::size_t>(j)].name));
  c_ = VecD::Zero(n);
  c_.head(model.legLinks()).setConstant(1.0 / model.legLinks());
  // phi = c . M^-1 q: theta_i = q_0 - sum_{1<=j<=i} q_j (toAbsolute).
  w_ = Eigen::RowVectorXd::Zero(n);
  w_(0) = c_.sum();
  for (int j = 1; j < n; ++j) w_(j) = -c_.tail(n - j).sum();
  const double duration = ref.touchdownTime();
  const auto knot = [&](double t) { return ref.at(gaits::Phase::kSsp, t); };
  for (int i = 0; i < kCheckSamples; ++i) {
    const double t = duration * i / (kCheckSamples - 1);
    if (!(c_.dot(knot(t).dtheta) > 0))
      throw std::invalid_argument(fmt::format(
          "HZD: the phase variable (mean stance-leg angle) does not grow at t = {:.4g} s", t));
  }

  // Impact invariance (Westervelt 2003 sec. V-C): the touchdown node, and its relabelled impact
  // image as the first node (the gait's own curvature there).
  const gaits::Knot end = knot(duration);
  single_impact_ = !dynamics::doubleImpact(model, end.theta, end.dtheta).unilateral_ok;
  const ImpactImage image = hzdImpact(model, end.theta, end.dtheta, single_impact_);
  phi_minus_ = phase(end.theta);
  phi_plus_ = phase(image.theta);
  gaits::Knot first = node(model, knot(0));
  first.t = phi_plus_;
  first.theta = actuated(image.theta);
  first.dtheta = slope(c_, image.dtheta);
  std::vector<gaits::Knot> knots{first};
  for (int k = 1; k < nodes - 1; ++k) {
    const double phi = phi_plus_ + (phi_minus_ - phi_plus_) * k / (nodes - 1);
    double lo = 0, hi = duration;  // phi grows with t: bisection on the step clock
    for (int i = 0; i < kBisections; ++i)
      (phase(knot((lo + hi) / 2).theta) < phi ? lo : hi) = (lo + hi) / 2;
    knots.push_back(node(model, knot((lo + hi) / 2)));
  }
  knots.push_back(node(model, end));
  spline_ = gaits::Trajectory(model.name(), 0, std::move(knots));
  for (int i = 0; i < kCheckSamples; ++i) {
    const gaits::Knot k = knot(duration * i / (kCheckSamples - 1));
    fit_error_ = std::max(fit_error_, output(k.theta).cwiseAbs().maxCoeff());
  }
}

VirtualConstraints::Value VirtualConstraints::at(double phi) const {
  // Beyond the ends (a perturbed or late step) h_d continues as its quadratic Taylor expansion.
  const double clamped = std::clamp(phi, phi_plus_, phi_minus_), d = phi - clamped;
  const gaits::Knot k = spline_.at(clamped);
  return {k.theta + k.dtheta * d + k.ddtheta * (d * d / 2), k.dtheta + k.ddtheta * d, k.ddtheta};
}

VecD VirtualConstraints::output(const VecD& theta) const {
  return actuated(theta) - at(phase(theta)).h;
}

VecD VirtualConstraints::outputRate(const VecD& theta, const VecD& dtheta) const {
  return actuated(dtheta) - at(phase(theta)).dh * c_.dot(dtheta);
}

VecD VirtualConstraints::absoluteFromActuated(double phi, const VecD& qa) const {
  const int n = static_cast<int>(c_.size());
  VecD q(n);
  q(0) = (phi - w_.tail(n - 1).dot(qa)) / w_(0);
  q.tail(n - 1) = qa;
  return dynamics::toAbsolute<double>(q);
}

VecD VirtualConstraints::posture(double phi) const {
  return absoluteFromActuated(phi, at(phi).h);
}

VecD VirtualConstraints::tangent(double phi) const {
  // Linear in q: dtheta/dphi = M^-1 (dq_0/dphi, dh/dphi) with dq_0 from w . dq/dphi = 1.
  const int n = static_cast<int>(c_.size());
  const VecD dh = at(phi).dh;
  VecD dq(n);
  dq(0) = (1 - w_.tail(n - 1).dot(dh)) / w_(0);
  dq.tail(n - 1) = dh;
  return dynamics::toAbsolute<double>(dq);
}

}  // namespace gaitopt::sim
