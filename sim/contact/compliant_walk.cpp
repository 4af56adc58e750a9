#include "sim/contact/compliant_walk.hpp"

#include <cmath>
#include <string>

#include <Eigen/Cholesky>

#include "dynamics/floating_base_dynamics.hpp"
#include "sim/walk/event_integrator.hpp"

namespace gaitopt::sim {
namespace {

/// Ground forces on the robot at B and E, and the anchors to carry on (Addi & Rodic 59-62).
struct CompliantForces {
  TipForces force;
  Vec2d anchor;
};

/// Impedance contact at one tip from its world position p and velocity pdot; penetration = -y.
ImpedanceContactForce tipForce(const ImpedanceGround& g, const Vec2d& p, const Vec2d& pdot,
                               double anchor) {
  return impedanceContactForce(g, {-p(1), -pdot(1), p(0), pdot(0)}, anchor);
}

CompliantForces contactForces(const dynamics::Model& plant, const ImpedanceGround& g,
                              const Eigen::VectorXd& q, const Eigen::VectorXd& v,
                              const Vec2d& anchor) {
  const auto b = tipForce(g, q.head<2>(), v.head<2>(), anchor(0));
  const auto e = tipForce(g, dynamics::floatingSwingTip(plant, q),
                          dynamics::floatingSwingTipVelocity(plant, q, v), anchor(1));
  return {{Vec2d(b.tangential, b.normal), Vec2d(e.tangential, e.normal)},
          Vec2d(b.anchor, e.anchor)};
}

ImpedanceGround withPlantFriction(const dynamics::Model& plant, const CompliantGround& ground) {
  ImpedanceGround g = ground.contact;
  g.friction = plant.friction();
  return g;
}

/// The depth at which the ground carries `normal_force` at rest, k delta^n = F [m].
double staticDepth(const ImpedanceGround& g, double normal_force) {
  return normal_force > 0 ? std::pow(normal_force / g.stiffness, 1 / g.exponent) : 0.0;
}

}  // namespace

ContactStep compliantContactStep(const dynamics::Model& plant, const CompliantGround& ground,
                                 const FreeBaseState& s, const TorqueFeedback& torque) {
  const ImpedanceGround g = withPlantFriction(plant, ground);
  const int n = plant.nLinks(), nq = n + 2;
  // x = (q, v, w): xdot = (v, D_ext^-1 (M^T tau - b + J_B^T F_B + J_E^T F_E), P_ext), with
  // P_ext the power of torques and ground forces, so w is their work over the step.
  const Rhs rhs = [&](double dt, const Eigen::VectorXd& x) {
    const Eigen::VectorXd q = x.head(nq), v = x.segment(nq, nq);
    const auto fb = dynamics::floatingBaseDynamics(plant, q.tail(n), v.tail(n));
    const TipForces f = contactForces(plant, g, q, v, s.anchor).force;
    const Eigen::VectorXd external = dynamics::floatingBaseActuation(plant, torque(dt, q, v)) +
                                     fb.jac_b.transpose() * f.b + fb.jac_e.transpose() * f.e +
                                     hipForce(plant, q, s.hip_force);
    Eigen::VectorXd xdot(2 * nq + 1);
    xdot << v, fb.mass.llt().solve(external - fb.bias), external.dot(v);
    return xdot;
  };
  Eigen::VectorXd x(2 * nq + 1);
  x << s.q, s.v, 0;
  x = rk4Step(rhs, 0.0, x, ground.time_step);
  ContactStep out{{x.head(nq), x.segment(nq, nq), s.anchor}, {}, ""};
  // Energy the integrator made: an unstable explicit step creates it exponentially, long
  // before the state overflows (and often first as a tip launched off the ground).
  const double created =
      freeBaseEnergy(plant, out.next.q, out.next.v) - freeBaseEnergy(plant, s.q, s.v) - x(2 * nq);
  if (std::string why = divergedStep(ground.time_step, created); !why.empty())
    out.failure = why + " (too long for this ground)";
  const CompliantForces end = contactForces(plant, g, out.next.q, out.next.v, s.anchor);
  out.force = end.force;
  out.next.anchor = end.anchor;
  return out;
}

WalkResult walkCompliant(const dynamics::Model& plant, const Controller& controller,
                         const Reference& ref, const CompliantGround& ground, const WalkPlan& plan,
                         const WalkLog& log, const VecD& theta0, const VecD& dtheta0) {
  validateImpedanceGround(withPlantFriction(plant, ground));
  const FreeBaseGround free_base{"compliant", ground.time_step,
                                 [&](const FreeBaseState& s, const TorqueFeedback& torque) {
                                   return compliantContactStep(plant, ground, s, torque);
                                 },
                                 staticDepth(ground.contact, ref.start().force_stance(1))};
  return walkFreeBase(plant, controller, ref, free_base, plan, log, theta0, dtheta0);
}

}  // namespace gaitopt::sim
