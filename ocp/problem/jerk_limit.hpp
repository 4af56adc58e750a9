#pragma once
/// @file jerk_limit.hpp
/// A bound on how fast every link's angular acceleration changes between consecutive
/// collocation points (config constraints.jerk_limit J [rad/s^3]):
///   -J <= (ddtheta_{p+1} - ddtheta_p) / (t_{p+1} - t_p) <= J,
/// written as two rows free of divisions, a_{p+1} - a_p - J dt_p T <= 0 and
/// a_{p+1} - a_p + J dt_p T >= 0 (dt_p the points' spacing per unit duration T), linear also when
/// T is free. Hermite-Simpson's acceleration is quadratic on a segment, so its slope at the
/// segment's ends is at most twice the bound on the half-segments: |theta'''| <= 2 J.
/// Why: the export's rates are the exact derivatives of its angles, but a check by differences
/// of 1 kHz samples carries the truncation error h^2/6 |theta'''| <= h^2 J / 3; the least
/// cost-of-transport gait's swing shank had |theta'''| near 10^5 rad/s^3 before touchdown, a
/// 0.3 % error of the peak rate.
#include <string>

#include "ocp/problem/point_stencil_bound.hpp"

namespace gaitopt::ocp {

/// The stencils {a_p, a_{p+1}} with weights (-1, 1) and allowance t_{p+1} - t_p per unit T.
class JerkLimit : public PointStencilBound {
 public:
  JerkLimit(std::string name, const Phase& phase, double jerk);
  /// Rows 2 n p .. 2 n (p + 1) - 1 bound the change from point p to point p + 1.
  GridNode nodeOf(int row) const override { return {"point", stencilOf(row), entryOf(row)}; }
};

}  // namespace gaitopt::ocp
