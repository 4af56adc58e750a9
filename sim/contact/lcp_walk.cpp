#include "sim/contact/lcp_walk.hpp"

#include <string>
#include <vector>

#include "dynamics/floating_base_dynamics.hpp"
#include "sim/contact/lcp_contact_step.hpp"

namespace gaitopt::sim {
namespace {

/// A tip as a contact of the LCP: n = d(tip y)/dq, t = d(tip x)/dq, gap = tip height.
struct TipContact {
  Eigen::MatrixXd jacobian;  ///< 2 x nq
  Vec2d position, velocity;  ///< world [m], [m/s]
};

bool nearGround(const TipContact& tip, double h) {
  return tip.position(1) < tip.velocity.norm() * h + kLcpActivationMargin;
}

}  // namespace

ContactStep lcpGroundStep(const dynamics::Model& plant, const LcpGround& ground,
                          const FreeBaseState& s, const TorqueFeedback& torque) {
  const int n = plant.nLinks();
  const double h = ground.time_step;
  const auto fb = dynamics::floatingBaseDynamics(plant, s.q.tail(n), s.v.tail(n));
  const TipContact tips[2] = {{fb.jac_b, s.q.head<2>(), s.v.head<2>()},
                              {fb.jac_e, dynamics::floatingSwingTip(plant, s.q), fb.jac_e * s.v}};
  std::vector<ContactRows> rows;
  std::vector<int> active;  // which tip each contact row belongs to
  for (int i = 0; i < 2; ++i) {
    if (!nearGround(tips[i], h)) continue;
    rows.push_back(
        {tips[i].jacobian.row(1), tips[i].jacobian.row(0), tips[i].position(1), plant.friction()});
    active.push_back(i);
  }
  const Eigen::VectorXd f = dynamics::floatingBaseActuation(plant, torque(0.0, s.q, s.v)) +
                            hipForce(plant, s.q, s.hip_force) - fb.bias;
  ContactStep out{s, {}, ""};
  if (!f.allFinite()) {  // lcpContactStep would throw; the walk reports it as a failure
    out.failure = "diverged: non-finite generalised force";
    return out;
  }
  const LcpStepResult lcp = lcpContactStep(fb.mass, f, s.v, h, rows);
  if (lcp.status != LemkeStatus::kSolved) {
    out.failure = std::string("LCP not solved (") + toString(lcp.status) + ")";
    return out;
  }
  out.next.v = lcp.velocity;
  out.next.q = s.q + h * lcp.velocity;
  for (std::size_t c = 0; c < active.size(); ++c) {
    const auto i = static_cast<Eigen::Index>(c);
    const Vec2d force(lcp.tangential_impulse(i) / h, lcp.normal_impulse(i) / h);
    (active[c] == 0 ? out.force.b : out.force.e) = force;
  }
  return out;
}

WalkResult walkLcp(const dynamics::Model& plant, const Controller& controller, const Reference& ref,
                   const LcpGround& ground, const WalkPlan& plan, const WalkLog& log,
                   const VecD& theta0, const VecD& dtheta0) {
  const FreeBaseGround free_base{"lcp", ground.time_step,
                                 [&](const FreeBaseState& s, const TorqueFeedback& torque) {
                                   return lcpGroundStep(plant, ground, s, torque);
                                 }};
  return walkFreeBase(plant, controller, ref, free_base, plan, log, theta0, dtheta0);
}

}  // namespace gaitopt::sim
