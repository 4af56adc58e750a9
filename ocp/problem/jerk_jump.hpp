#pragma once
/// @file jerk_jump.hpp
/// A bound on how much every link's jerk jumps where two segments of a phase meet (config
/// constraints.jerk_jump_limit J [rad/s^3]). Between the points a segment's acceleration is the
/// polynomial of its scheme (quadratic through node, midpoint and node in Hermite-Simpson, linear
/// in trapezoidal; collocation_interpolation.hpp), so it is continuous at a shared node but its
/// slope, the jerk, is not. At node k, with the left segment's end slope and the right one's start
/// slope (Hermite-Simpson: (a_{k-1} - 4 a_m + 3 a_k) / h_L and (-3 a_k + 4 a_m' - a_{k+1}) / h_R),
///   -J <= jerk_right - jerk_left <= J,
/// written free of divisions by T (h = T dt): T (jerk_right - jerk_left) is linear in the
/// accelerations, so the two rows L(a) - J T <= 0 and L(a) + J T >= 0 are linear also when T is
/// free.
/// Why: a central difference of rates sampled at spacing h across such a node differs from the
/// acceleration by about h / 4 times the jump; that kink, not the smooth part, is what the export
/// check of docs/optimal_gaits.md ("What holds on the export") finds in an optimum. jerk_limit.hpp
/// bounds the jerk itself, which also costs where the jerk is large but smooth.
#include <string>

#include "ocp/problem/point_stencil_bound.hpp"

namespace gaitopt::ocp {

/// One stencil per node strictly inside the phase, over the points of the two segments that
/// meet there, with allowance 1.
class JerkJump : public PointStencilBound {
 public:
  JerkJump(std::string name, const Phase& phase, double jump);
  /// Rows 2 n (k - 1) .. 2 n k - 1 bound the jump at node k (1 .. segments - 1), the point in the
  /// middle of its stencil.
  GridNode nodeOf(int row) const override {
    const PointStencil& s = stencil(stencilOf(row));
    return {"point", s.points[s.points.size() / 2], entryOf(row)};
  }
};

}  // namespace gaitopt::ocp
