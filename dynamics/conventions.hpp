#pragma once
/// @file conventions.hpp
/// The one place that owns gaitopt's conventions; everything else uses it. For readers they are
/// stated in docs/design.md#conventions.
///
/// Frames and units: SI units, radians. x points in the walking direction, y up. Every step is
/// expressed in the frame whose origin is the stance tip B. On a slope (Model::slope(), > 0
/// uphill) this is the GROUND frame: x along the slope, y along its normal, the ground y = 0,
/// theta from the slope normal; only gravity rotates, to (-g sin gamma, -g cos gamma).
///
/// Links are numbered along the serial chain from the stance tip (Mu 2004, Fig. 2.1): for the
/// five-link robot 1 stance shank, 2 stance thigh, 3 torso, 4 swing thigh, 5 swing shank. In code
/// they are 0-based (index 0 = stance shank). A link whose `continues` flag (Mu's a_i) is false is
/// a terminal branch (the torso): the chain's next link starts at that link's proximal joint.
///
/// Absolute angles theta_i (Mu 2.1-2.2 as written): the unit vector of link i, from its proximal
/// joint toward its distal end, is u_i = (sin theta_i, cos theta_i). So theta = 0 is upright and
/// theta grows clockwise (toward +x); a hanging swing leg has theta ~ pi. Counter-clockwise angular
/// velocity is omega_i = -dtheta_i.
///
/// Relative joint angles q = M theta (Mu 2.41): q0 = theta_1 (stance ankle, from the vertical),
/// q_j = theta_j - theta_{j+1} (1-based) for the joint between links j and j+1. For the five-link
/// robot: q1 stance knee, q2 stance hip (torso - stance thigh), q3 swing hip, q4 swing knee.
/// Joint torques tau (q-space) map to generalised torques on theta by T_theta = M^T tau (2.43).
///
/// Ankle torque: tau0 acts between the ground and link 1 at the stance tip B. In the double
/// support phase (before relabelling) B is the trailing foot; the leading tip E is a pinned
/// point foot without ankle torque. The ground moment on the robot at B is -tau0 (ccw positive).
///
/// A step: SSP (B pinned) -> impact at E -> DSP (B and E pinned, E = B + (step_length, 0)) ->
/// relabel (2.38, corrected) -> next step.
#include <limits>

#include <Eigen/Core>

#include "config/units.hpp"  // kDeg: one degree in radians (pi is std::numbers::pi)

namespace gaitopt {

/// Largest chain the fixed-capacity matrices hold (five-link robots use 5).
inline constexpr int kMaxLinks = 7;

/// The start of a running minimum (a least margin before any sample lowers it).
inline constexpr double kInfinity = std::numeric_limits<double>::infinity();

template <class S>
using Vec = Eigen::Matrix<S, Eigen::Dynamic, 1, 0, kMaxLinks, 1>;
template <class S>
using Mat = Eigen::Matrix<S, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxLinks, kMaxLinks>;
/// Residual vectors: the n dynamics rows plus up to two constraint rows.
template <class S>
using VecR = Eigen::Matrix<S, Eigen::Dynamic, 1, 0, kMaxLinks + 2, 1>;
template <class S>
using Vec2 = Eigen::Matrix<S, 2, 1>;
template <class S>
using Mat2X = Eigen::Matrix<S, 2, Eigen::Dynamic, 0, 2, kMaxLinks>;

using VecD = Vec<double>;
using MatD = Mat<double>;
using Vec2d = Vec2<double>;
using Mat2Xd = Mat2X<double>;

}  // namespace gaitopt
