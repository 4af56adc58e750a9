#pragma once
/// @file leg_ik.hpp
/// Inverse kinematics of one two-link leg (Mu 2004 eq. 3.24, written for the absolute-angle
/// convention of dynamics/conventions.hpp), with exact rates and accelerations.
#include <Eigen/Core>

namespace gaitopt::gaits {

enum class KneeDirection { kForward, kBackward };

/// Position, velocity and acceleration of the distal point relative to the proximal one.
struct PointMotion {
  Eigen::Vector2d pos = Eigen::Vector2d::Zero();
  Eigen::Vector2d vel = Eigen::Vector2d::Zero();
  Eigen::Vector2d acc = Eigen::Vector2d::Zero();
};

/// Angles of the two links (proximal link a, distal link b) and their derivatives.
struct LegAngles {
  Eigen::Vector2d theta, dtheta, ddtheta;
};

/// Whether legInverseKinematics solves for the distal point at `r` (relative to the proximal
/// one): |l_a - l_b| < |r| < l_a + l_b and the leg not horizontal. No trigonometry, for searches
/// that only need to know.
bool legCanReach(double l_a, double l_b, const Eigen::Vector2d& r);

/// Solves l_a u(alpha) + l_b u(beta) = r (u = (sin, cos)) with the knee on the +x side of the
/// line from the proximal to the distal point (kForward) or the -x side, then
/// dtheta = J^-1 rdot and ddtheta = J^-1 (rddot - Jdot dtheta).
/// @throws std::domain_error naming the distance and the reachable range when
///         |l_a - l_b| < |r| < l_a + l_b fails, or when the leg is horizontal.
LegAngles legInverseKinematics(double l_a, double l_b, const PointMotion& r, KneeDirection knee);

}  // namespace gaitopt::gaits
