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

#include "ocp/collocation.hpp"

namespace gaitopt::ocp {

/// The segment holding phase time t (clamped to the phase), for duration `total`.
int segmentAt(const PhaseLayout& layout, double t, double total);

/// The point variables [x, xdot, u, z] at phase time t of the solution `decision`.
Eigen::VectorXd interpolatePoint(const PhaseLayout& layout, const Eigen::VectorXd& decision,
                                 double t);

}  // namespace gaitopt::ocp
