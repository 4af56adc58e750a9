#pragma once
/// @file metrics.hpp
/// Gait metrics, one function each, shared by the polynomial gait and the optimiser's reports
/// (DESIGN.md sec. 5, summary.json). Integrals use the trapezoidal rule over the knots of each
/// phase (a zero-length interval at a phase switch contributes nothing).
#include <Eigen/Core>

#include "dynamics/model.hpp"
#include "gaits/trajectory.hpp"

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
/// relative to B [m]. Mirrors dynamics::centreOfPressure.
double zmpX(const Knot& knot, double step_length);
/// Smallest signed distance from the ZMP to the support boundary [m]: SSP support
/// [-heel, toe] around B; DSP support [-heel, step_length + toe]. Negative when outside.
double minZmpMargin(const Trajectory& traj, const dynamics::Model& model);
/// Norm of the jump in dtheta that the rigid double impact (Mu 2.28) would cause at touchdown,
/// from the last SSP knot [rad/s]; zero for a trajectory without a DSP.
double touchdownVelocityJump(const Trajectory& traj, const dynamics::Model& model);
/// Kinetic energy lost in that impact [J].
double impactEnergyLoss(const Trajectory& traj, const dynamics::Model& model);

}  // namespace gaitopt::gaits
