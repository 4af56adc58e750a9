#include "sim/walk/rigid_contact_loop.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "dynamics/floating_base_dynamics.hpp"

namespace gaitopt::sim {

using gaits::Phase;

ContactLoop::ContactLoop(const dynamics::Model& plant, const Controller& controller,
                         const Reference& ref, Phase phase, PhaseStart start,
                         const ContactSet& contacts, const ContactRules& rules,
                         const std::optional<Push>& push, int step)
    : plant_(plant),
      controller_(controller),
      ref_(ref),
      phase_(phase),
      start_(std::move(start)),
      contacts_(contacts),
      rules_(rules),
      push_(push),
      step_(step) {}

const ContactLoop::State& ContactLoop::at(double t, const Eigen::VectorXd& x) const {
  if (cached_ && cached_t_ == t && cached_x_ == x) return cached_state_;
  cached_state_ = evaluate(t, x);
  cached_t_ = t;
  cached_x_ = x;
  cached_ = true;
  return cached_state_;
}

Eigen::VectorXd ContactLoop::rhs(double t, const Eigen::VectorXd& x) const {
  const State& s = at(t, x);
  Eigen::VectorXd dx(x.size());
  dx << s.qdot, s.qddot, s.memory_rate;
  return dx;
}

bool ContactLoop::ankleLimited() const {
  return plant_.joints().front().actuated && contacts_.b.onGround();
}

ContactLoop::State ContactLoop::evaluate(double t, const Eigen::VectorXd& x) const {
  const int n = plant_.nLinks();
  State s;
  s.qdot = x.segment(n + 2, n + 2);
  s.theta = x.segment(2, n);
  s.dtheta = s.qdot.tail(n);
  s.memory = contactMemory(x, n);
  s.ref = ref_.at(phase_, t, start_);
  ControlOutput u = controller_.control(phase_, s.theta, s.dtheta, s.ref, s.memory);
  s.tau = std::move(u.tau);
  s.memory_rate = std::move(u.memory_rate);
  const Vec2d pushed =
      phase_ == Phase::kSsp ? pushForce(push_, step_, t, ref_.touchdownTime()) : Vec2d::Zero();
  auto acc = contactDynamics(plant_, s.theta, s.dtheta, s.tau, contacts_, pushed);
  s.qddot = acc.qddot;
  s.force_stance = acc.force_b;
  s.force_swing = acc.force_e;
  s.cop_margin = std::numeric_limits<double>::infinity();
  if (ankleLimited()) limitAnkle(s, pushed);
  s.power = power(s, pushed);
  return s;
}

void ContactLoop::limitAnkle(State& s, const Vec2d& pushed) const {
  const dynamics::Foot& foot = plant_.foot();
  const double fy = s.force_stance(1), tau0 = s.tau(0);
  s.cop_moment = dynamics::copMomentMargin(tau0, fy, foot);
  s.cop_margin = phase_ == Phase::kSsp
                     ? loadedCopMargin(tau0, fy, foot, plant_.totalMass() * plant_.gravity())
                     : std::numeric_limits<double>::infinity();
  const bool saturate = rules_.cop_limit == CopLimit::kSaturate || phase_ == Phase::kDsp;
  if (saturate && s.cop_moment < 0) saturateAnkle(s, pushed);
}

double ContactLoop::power(const State& s, const Vec2d& pushed) const {
  double p = dynamics::floatingBaseActuation(plant_, s.tau).dot(s.qdot);
  if (!pushed.isZero())
    p += pushed.dot(dynamics::floatingJacobian(plant_.hipWeights(), s.theta) * s.qdot);
  if (contacts_.b.mode == TipContact::Mode::kSlide) p += s.force_stance(0) * s.qdot(0);
  if (contacts_.e.mode == TipContact::Mode::kSlide)
    p += s.force_swing(0) * (dynamics::floatingJacobian(plant_.tipWeights(), s.theta) * s.qdot)(0);
  return p;
}

void ContactLoop::saturateAnkle(State& s, const Vec2d& pushed) const {
  const dynamics::Foot& foot = plant_.foot();
  const double tau0 = s.tau(0), fy = s.force_stance(1);
  VecD probe = s.tau;
  probe(0) += 1.0;
  const double slope =
      contactDynamics(plant_, s.theta, s.dtheta, probe, contacts_, pushed).force_b(1) - fy;
  const double unloaded = fy - slope * tau0;  // F_By at tau0 = 0
  // The ends of dynamics::ankleTorqueRange at the load the torque itself changes:
  // tau0 = heel F_By(tau0) and tau0 = -toe F_By(tau0), the CoP on the heel or on the toe.
  const double upper = foot.heel * unloaded / (1 - foot.heel * slope);
  const double lower = -foot.toe * unloaded / (1 + foot.toe * slope);
  s.tau(0) = unloaded > 0 ? std::max(lower, std::min(tau0, upper)) : 0.0;
  const auto acc = contactDynamics(plant_, s.theta, s.dtheta, s.tau, contacts_, pushed);
  s.qddot = acc.qddot;
  s.force_stance = acc.force_b;
  s.force_swing = acc.force_e;
  s.saturated = true;
}

Eigen::VectorXd contactMemory(const Eigen::VectorXd& x, int n_links) {
  return x.tail(x.size() - 2 * (n_links + 2));
}

Eigen::VectorXd contactState(const VecD& theta, const VecD& dtheta, double x_b, const Vec2d& v_b,
                             int memory) {
  const auto n = theta.size();
  Eigen::VectorXd x(2 * n + 4 + memory);
  x << x_b, 0, theta, v_b, dtheta, Eigen::VectorXd::Zero(memory);
  return x;
}

}  // namespace gaitopt::sim
