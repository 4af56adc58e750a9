#pragma once
/// @file free_base_walk.hpp
/// Walking on a ground that is not rigid-with-events: the chain with a free base
/// (dynamics/floating_base_dynamics.hpp) advanced by a fixed time step through a contact law at
/// both tips, B (stance) and E (swing). The contact law is the only thing that differs between
/// grounds (compliant_walk.hpp: Hunt-Crossley with RK4; lcp_walk.hpp: Stewart-Trinkle time
/// stepping); the phases, relabelling and failures are here, once.
///   SSP: the controller runs on the step clock from the reference start, the robot's departure
///   from it faded out (reference.hpp PhaseStart; not at touchdown). Touchdown: the first
///   step at whose end E, ahead of B, carries a normal force > 0 or is at or below the ground;
///   the clock jumps to the reference touchdown time.
///   DSP (only if the reference has one): until the reference ends or, in its second half, the
///   trailing tip B has carried no normal force for kUnloadTime. Then relabel (Mu 2.38): the base
///   moves to E, the tips swap roles (and anchors), the next SSP starts with the clock at 0.
///   Failures: the rule of contact_rules.hpp, as on rigid ground (a fall; a tip on the ground
///   sliding more than max_slip from where it was set down within the step; the stance foot's
///   CoP, at the last time step's normal force, leaving the foot when the rules fail it, else the
///   ankle torque saturates; a stance tip without normal force for kLiftoffTime, the ground's
///   "pull"), no step end within 3x the planned step, a contact law failure, and "diverged" (a
///   non-finite state or a tip deeper than kMaxPenetration, what an explicit integrator does on
///   too stiff a ground).
#include <functional>
#include <string>

#include <Eigen/Core>

#include "dynamics/model.hpp"
#include "sim/controllers/reference.hpp"
#include "sim/controllers/tracking_controller.hpp"
#include "sim/walk/hybrid_walk.hpp"

namespace gaitopt::sim {

/// The free-base chain in the world frame, plus the memory of a compliant ground.
struct FreeBaseState {
  Eigen::VectorXd q;                ///< (x_b, y_b, theta_1..theta_n) [m, rad], n + 2
  Eigen::VectorXd v;                ///< dq/dt, n + 2
  Vec2d anchor = Vec2d::Zero();     ///< tangential spring anchors (x) at B and E [m]; see
                                    ///< impedanceContactForce (unused by rigid contact laws)
  Vec2d hip_force = Vec2d::Zero();  ///< a push on the hip, held over the time step [N]
};

/// Ground forces on the robot at the tips [N].
struct TipForces {
  Vec2d b = Vec2d::Zero();
  Vec2d e = Vec2d::Zero();
};

/// Joint torques at elapsed time dt within the time step and state (q, v): the controller as the
/// contact law sees it (RK4 evaluates it at its stages).
using TorqueFeedback =
    std::function<VecD(double dt, const Eigen::VectorXd& q, const Eigen::VectorXd& v)>;

/// One time step of a contact law.
struct ContactStep {
  FreeBaseState next;
  TipForces force;              ///< at the end of the step, or its average over the step
  std::string failure;          ///< "" unless the law could not take the step
  double stance_foot_tilt = 0;  ///< B's foot's turn from flat: feet that are bodies (DART) [rad]
};

using ContactLaw = std::function<ContactStep(const FreeBaseState&, const TorqueFeedback&)>;

/// A ground as the free-base walk sees it.
struct FreeBaseGround {
  std::string name;  ///< StepResult::impact: "compliant" or "lcp"
  double time_step;  ///< h > 0 [s]
  ContactLaw step;
  /// The stance tip starts this far into the ground [m]: a compliant ground carries the
  /// reference's first stance force only when pressed in (at zero depth the tip carried 0.015 N
  /// and the first ankle torque already put the centre of pressure off the foot).
  double start_depth = 0;
};

/// A stance tip without normal force for this long has left the ground [s].
inline constexpr double kLiftoffTime = 0.02;
/// The trailing tip counts as unloaded (the DSP ends) after this long without normal force [s].
inline constexpr double kUnloadTime = 0.005;
/// Deeper than this, the contact law has failed (a hard floor sinks by about a millimetre) [m].
inline constexpr double kMaxPenetration = 0.05;

/// Largest energy one RK4 step may create [J]: the change of kinetic plus potential energy
/// minus the work of torques and ground forces, integrated alongside the state. Well-resolved
/// steps of the five-link walk on configs/grounds/impedance.yaml make < 3e-5 J, on rigid ground
/// < 3e-6 J (the optimum under every law, 20 steps); a step beyond the impedance ground's
/// stability limit makes > 0.05 J within a few steps and then grows exponentially, and one
/// through a singular rigid contact made 9e28 J (rigid_step.cpp).
inline constexpr double kMaxCreatedEnergy = 0.01;

/// Kinetic plus potential energy of the free-base chain at (q, v) (Mu 2.3-2.4 with the base at
/// (x_b, y_b); on a slope the base term is -m g_vec . (x_b, y_b) in the ground frame) [J].
double freeBaseEnergy(const dynamics::Model& plant, const Eigen::VectorXd& q,
                      const Eigen::VectorXd& v);

/// "" when an RK4 step of `time_step` created at most kMaxCreatedEnergy, else the walk's
/// failure "diverged: an RK4 step of h s created E J" (a NaN or Inf energy too).
std::string divergedStep(double time_step, double created);

/// The generalised force J_H^T F of a force F on the hip (zero when F is).
Eigen::VectorXd hipForce(const dynamics::Model& plant, const Eigen::VectorXd& q,
                         const Vec2d& force);

/// The free-base state of a step start with B resting at the world point (x_b, y_b).
FreeBaseState freeBaseStart(const dynamics::Model& plant, const VecD& theta, const VecD& dtheta,
                            double x_b = 0, double y_b = 0);

/// Up to plan.steps steps (with the push where it acts) from the reference's start, or
/// (theta0, dtheta0) when given; fills the same WalkResult as simulateWalk (impact = ground.name).
/// @throws std::invalid_argument when ground.time_step is not positive and finite.
WalkResult walkFreeBase(const dynamics::Model& plant, const Controller& controller,
                        const Reference& ref, const FreeBaseGround& ground, const WalkPlan& plan,
                        const WalkLog& log = {}, const VecD& theta0 = {}, const VecD& dtheta0 = {});

}  // namespace gaitopt::sim
