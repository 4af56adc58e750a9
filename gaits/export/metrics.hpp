#pragma once
/// @file metrics.hpp
/// Gait metrics, one function each, shared by the polynomial gait and the optimiser's reports
/// (summary.json, docs/design.md#the-export-contract). Integrals use the trapezoidal rule over the
/// knots of each phase (a zero-length interval at a phase switch contributes nothing).
#include <optional>

#include <Eigen/Core>

#include "dynamics/model.hpp"
#include "gaits/trajectory/trajectory.hpp"

namespace gaitopt::gaits {

/// Absolute mechanical work over the step, integral of sum_j |tau_j dq_j/dt| [J].
double absoluteWork(const Trajectory& traj);
/// Integral of sum_j tau_j^2 [N^2 m^2 s].
double torqueSquaredIntegral(const Trajectory& traj);
/// absoluteWork / (m g step_length) [-].
double costOfTransport(const Trajectory& traj, const dynamics::Model& model);
/// max_t |tau_j| for each joint j [N m] (n).
Eigen::VectorXd peakTorque(const Trajectory& traj);
/// Smallest vertical ground force over the step at every tip in contact (B always, E in DSP) [N].
double minNormalForce(const Trajectory& traj);
/// Largest |F_x| / F_y at any tip in contact: the friction coefficient the gait needs [-].
double maxFrictionRatio(const Trajectory& traj);
/// x of the ZMP (centre of pressure of the tip forces and the ground moment -tau0 at B),
/// relative to B [m]. dynamics::centreOfPressure of the knot.
double zmpX(const Knot& knot, double step_length);
/// Smallest signed distance from the ZMP to the support boundary [m]: SSP support
/// [-heel, toe] around B; DSP support [-heel, step_length + toe]. Negative when outside.
double minZmpMargin(const Trajectory& traj, const dynamics::Model& model);
/// How far a gait leaves the upright posture, largest over the knots [rad]: the torso's angle
/// from vertical, and each knee's flexion |theta_thigh - theta_shank| (0 straight) for the
/// stance leg (links 0, 1) and the swing leg (links n-2, n-1). Zero for what the robot lacks.
struct Posture {
  double torso_lean = 0;
  double stance_knee = 0;
  double swing_knee = 0;
};
Posture posture(const Trajectory& traj, const dynamics::Model& model);

/// The touchdown of a step: the last SSP knot before the DSP meets the rigid double impact
/// (Mu 2.27-2.28); an SSP-only step ends at its strike and meets the single impact (2.34-2.36,
/// the old stance tip B lifts off with trailing_velocity).
struct TouchdownImpact {
  size_t knot = 0;            ///< index of the pre-impact knot
  bool double_impact = true;  ///< else single
  VecD theta, dtheta_minus, dtheta_plus;
  Vec2d trailing_velocity = Vec2d::Zero();  ///< Xdot_b^+ [m/s], zero for a double impact
};
/// The impact at touchdown; empty for a step that neither has a DSP nor ends in the SSP.
/// @throws std::invalid_argument when trajectory and robot differ in links.
std::optional<TouchdownImpact> touchdownImpact(const Trajectory& traj,
                                               const dynamics::Model& model);
/// Norm of the jump in dtheta that this impact causes [rad/s] (zero when the swing tip
/// arrives at rest).
double touchdownVelocityJump(const Trajectory& traj, const dynamics::Model& model);
/// Kinetic energy lost in that impact, 1/2 dq-^T D dq- - 1/2 dq+^T D dq+ with q = (x_b, y_b,
/// theta) [J].
double impactEnergyLoss(const Trajectory& traj, const dynamics::Model& model);

}  // namespace gaitopt::gaits
