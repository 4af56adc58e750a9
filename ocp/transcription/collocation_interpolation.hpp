#pragma once
/// @file collocation_interpolation.hpp
/// The polynomials a collocation scheme implies between its points (Kelly, SIAM Review 2017,
/// trapezoidal and Hermite-Simpson interpolation), so that a solution is read between the
/// nodes exactly as the transcription assumed it:
///   trapezoidal:     xdot, u, z linear on a segment, x its integral (quadratic);
///   Hermite-Simpson: xdot, u, z quadratic through node, midpoint and node, x cubic.
/// In the second-order form x = (q, v) the derivative of q is the interpolated v of the points
/// and that of v the interpolated acceleration.
#include <Eigen/Core>
#include <array>

#include "ocp/transcription/collocation.hpp"

namespace gaitopt::ocp {

/// Weights of a segment's points, (0, 1) for trapezoidal, (0, 1/2, 1) for Hermite-Simpson.
using SegmentBasis = std::array<double, 3>;

/// The Lagrange basis on a segment's points at local time s = tau / h in [0, 1].
SegmentBasis lagrangeBasis(Scheme scheme, double s);

/// Integrals of the Lagrange basis from 0 to s, in units of h; at s = 1 they are the trapezoid
/// and Simpson weights, at s = 1/2 (5/24, 1/3, -1/24), the separated Hermite condition.
SegmentBasis lagrangeBasisIntegral(Scheme scheme, double s);

/// Integrals of lagrangeBasisIntegral from 0 to s, in units of h^2: with them q = q_k + v_k h s +
/// h^2 sum_j . a_j is the export's angle (exportPoint). At s = 1 they meet the scheme's own
/// position update: (1/6, 1/3, 0) for Hermite-Simpson, (1/3, 1/6) for trapezoidal.
SegmentBasis lagrangeDoubleIntegral(Scheme scheme, double s);

/// The segment holding phase time t (clamped to the phase), for duration `total`.
int segmentAt(const PhaseLayout& layout, double t, double total);

/// The point variables [x, xdot, u, z] at phase time t of the solution `decision`.
Eigen::VectorXd interpolatePoint(const PhaseLayout& layout, const Eigen::VectorXd& decision,
                                 double t);

/// As interpolatePoint, but in the second-order form q is the double integral of the
/// interpolated acceleration from the segment's first point (q_k + v_k tau + double integral
/// of a), so that q, v and a of the export are derivatives of one another, as a controller and
/// the simulator's quintic reference between samples take them. interpolatePoint's q integrates
/// the interpolated v instead, which differs from the integral of a by a cubic vanishing at the
/// three points: rates up to 2 % off the angles' derivatives. Both meet the points' q at the
/// segment ends (Simpson's rule integrates that cubic exactly); this one misses the midpoint's
/// q by O(h^4).
Eigen::VectorXd exportPoint(const PhaseLayout& layout, const Eigen::VectorXd& decision, double t);

}  // namespace gaitopt::ocp
