#pragma once
/// @file centre_of_pressure.hpp
/// The centre of pressure (CoP) of the ground reaction, the one place every other file takes it
/// from: the optimiser's ZMP rows (ocp/problem/ground_contact.cpp) in their linear form, the
/// export checks and metrics, and the simulators' foot-rotation rule. Conventions
/// (conventions.hpp): tau0 acts between the ground and link 1 at the stance tip B, so the ground
/// moment on the robot at B is -tau0; a foot reaches `heel` behind and `toe` ahead of its tip.
/// For a single contact the CoP is where the ground wrench has zero moment, x = -tau0 / F_By
/// (docs/derivations.md#ground-reactions-and-the-zmp).
#include <algorithm>
#include <limits>

#include "dynamics/model.hpp"

namespace gaitopt::dynamics {

/// The CoP of point contacts on the ground y = 0 (ground frame on a slope): the x where the ground
/// wrench has zero moment. `moment_b` is the ground moment on the robot at B (ccw, = -tau0) [m].
template <class S>
S centreOfPressure(const S& x_b, const Vec2<S>& force_b, const S& moment_b, const S& x_e,
                   const Vec2<S>& force_e) {
  return (x_b * force_b(1) + x_e * force_e(1) + moment_b) / (force_b(1) + force_e(1));
}

/// The stance foot's own CoP relative to B, -tau0 / F_By [m].
inline double stanceCop(double tau0, double force_y) {
  return -tau0 / force_y;
}

/// Distance of a CoP x (relative to its tip) inside [-heel, toe], negative outside [m].
inline double copMargin(double cop, const Foot& foot) {
  return std::min(cop + foot.heel, foot.toe - cop);
}

/// The same margin in moment form, min(heel F_y - tau0, toe F_y + tau0) [N m]: defined at any
/// load, and >= 0 exactly when F_y >= 0 and the CoP lies on the foot.
inline double copMomentMargin(double tau0, double force_y, const Foot& foot) {
  return std::min(foot.heel * force_y - tau0, foot.toe * force_y + tau0);
}

/// The ankle torques that keep the CoP on the foot under a normal force F_y >= 0:
/// -toe F_y <= tau0 <= heel F_y [N m].
struct AnkleTorqueRange {
  double lower;
  double upper;
};
inline AnkleTorqueRange ankleTorqueRange(double force_y, const Foot& foot) {
  const double fy = std::max(force_y, 0.0);
  return {-foot.toe * fy, foot.heel * fy};
}

}  // namespace gaitopt::dynamics
