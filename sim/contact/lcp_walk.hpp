#pragma once
/// @file lcp_walk.hpp
/// Walking on rigid ground by time stepping (Stewart & Trinkle 1996; the time-stepping form of
/// the contact LCP of Addi & Rodic 2010, eqs. 36, 43, 45, 56): each step of length h solves one
/// LCP (lcp_contact_step.hpp, Lemke) for the post-step velocity of the free-base chain with the
/// tips near the ground as unilateral frictional contacts, then q_next = q + h v_next
/// (semi-implicit Euler). Impacts need no separate map: they are the impulses of the step in
/// which a tip arrives. Phases, relabelling and failures: free_base_walk.hpp.
#include "sim/contact/ground_model.hpp"
#include "sim/walk/free_base_walk.hpp"

namespace gaitopt::sim {

/// A tip enters the LCP when its height is below its speed times h plus this [m]: it could
/// reach the ground within the step, and a resting tip never drops out of the problem.
inline constexpr double kLcpActivationMargin = 1e-3;

/// One time step of length ground.time_step with the torques held at their value at the start
/// (M = D_ext, f = M^T tau - b of floating_base_dynamics.hpp). Forces are impulses / h. A
/// Lemke failure gives failure = "LCP not solved (...)".
ContactStep lcpGroundStep(const dynamics::Model& plant, const LcpGround& ground,
                          const FreeBaseState& s, const TorqueFeedback& torque);

/// The walk of free_base_walk.hpp on this ground (impact = "lcp").
WalkResult walkLcp(const dynamics::Model& plant, const Controller& controller, const Reference& ref,
                   const LcpGround& ground, const WalkPlan& plan, const WalkLog& log = {},
                   const VecD& theta0 = {}, const VecD& dtheta0 = {});

}  // namespace gaitopt::sim
