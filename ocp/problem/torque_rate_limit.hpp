#pragma once
/// @file torque_rate_limit.hpp
/// A bound on how fast every joint torque changes between consecutive collocation points
/// (config constraints.torque_rate_limit R [N m/s]):
///   -R <= (u_{p+1} - u_p) / (t_{p+1} - t_p) <= R,
/// the rows of jerk_limit.hpp on the torques instead of the accelerations (point_stencil_bound.hpp:
/// free of divisions, linear also when the duration is free). Hermite-Simpson's torque is the
/// quadratic through a segment's three points, so its slope is at most 2 R.
/// Why: an actuator's torque has a bandwidth, and a cost that does not penalise the torque's size
/// (absolute work) has impulsive optima. Without the bound the absolute-work optimum of Mu's robot
/// moves its torques at up to 8e4 N m/s on its 1 kHz export, and its cost falls as the mesh
/// resolves the impulses (docs/optimal_gaits.md#a-torque-rate-bound-for-absolute-work).
#include <string>

#include "ocp/problem/point_stencil_bound.hpp"

namespace gaitopt::ocp {

class TorqueRateLimit : public PointStencilBound {
 public:
  TorqueRateLimit(std::string name, const Phase& phase, double rate);
  /// Rows 2 n p .. 2 n (p + 1) - 1 bound the change from point p to point p + 1.
  GridNode nodeOf(int row) const override { return {"point", stencilOf(row), entryOf(row)}; }
};

}  // namespace gaitopt::ocp
