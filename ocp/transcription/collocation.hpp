#pragma once
/// @file collocation.hpp
/// Direct collocation of one phase, independent of the robot (Betts 2010; Kelly, SIAM Review
/// 2017). A phase of fixed or free duration T is cut into segments (equal, or at given fractions
/// of T after mesh refinement); each collocation point carries
/// the state x, its time derivative xdot (so any dynamics enter as an implicit path constraint
/// F(x, xdot, u, z) = 0), inputs u and algebraic variables z (e.g. contact forces).
///   trapezoidal:     x_{k+1} - x_k - h/2 (xdot_k + xdot_{k+1}) = 0                 (order 2)
///   Hermite-Simpson, separated form (points 2k, 2k+1 = midpoint, 2k+2):
///     x_{2k+2} - x_{2k} - h/6 (xdot_{2k} + 4 xdot_{2k+1} + xdot_{2k+2}) = 0           (Simpson)
///     x_{2k+1} - (x_{2k} + x_{2k+2})/2 - h/8 (xdot_{2k} - xdot_{2k+2}) = 0         (order 4)
/// with h_k = T (s_{k+1} - s_k) for mesh fractions s. A free T is a decision variable; the
/// defects are then bilinear in T and xdot.
#include <string>
#include <vector>

#include "ocp/transcription/nlp.hpp"

namespace gaitopt::ocp {

enum class Scheme { kTrapezoidal, kHermiteSimpson };
const char* toString(Scheme scheme);
/// @throws std::invalid_argument for anything but "trapezoidal" or "hermite_simpson".
Scheme schemeFromString(const std::string& text);

/// Where one phase's variables live: points in time order, each contiguous.
/// First-order form (nq = 0): a point is [x, xdot, u, z].
/// Second-order form (nq > 0, x = (q, v), nx = 2 nq): a point is [q, v, a, u, z] and
/// xdot = (v, a) refers to the point's own v and a, so mechanical systems carry no duplicate
/// of v and no kinematic rows qdot = v.
struct PhaseLayout {
  Scheme scheme = Scheme::kHermiteSimpson;
  int segments = 0;
  double duration = 0;  ///< T when fixed; the initial T when free
  int nx = 0, nu = 0, nz = 0;
  int offset = 0;  ///< first variable of the phase in the decision vector
  int nq = 0;      ///< > 0: second-order form with nx = 2 nq
  /// Segment boundaries as fractions of T: segments + 1 increasing values from 0 to 1.
  /// Empty: equal segments.
  std::vector<double> mesh = {};
  int duration_index = -1;  ///< the variable holding T when the duration is free, else -1

  bool freeDuration() const { return duration_index >= 0; }
  /// T at the decision vector x.
  double durationAt(const Eigen::VectorXd& x) const {
    return freeDuration() ? x(duration_index) : duration;
  }
  int pointsPerSegment() const { return scheme == Scheme::kHermiteSimpson ? 2 : 1; }

  int points() const { return pointsPerSegment() * segments + 1; }
  int derivativeSize() const { return nq > 0 ? nq : nx; }  ///< xdot variables of a point
  int pointSize() const { return nx + derivativeSize() + nu + nz; }
  int variables() const { return points() * pointSize(); }
  int pointOffset(int p) const { return offset + p * pointSize(); }
  int x(int p, int i) const { return pointOffset(p) + i; }
  int xdot(int p, int i) const {
    if (nq > 0 && i < nq) return x(p, nq + i);  // dq/dt = v, stored in x
    return pointOffset(p) + nx + (nq > 0 ? i - nq : i);
  }
  int u(int p, int i) const { return pointOffset(p) + nx + derivativeSize() + i; }
  int z(int p, int i) const { return u(p, 0) + nu + i; }
  /// Boundary k of the segments as a fraction of T (k = 0 .. segments).
  double fraction(int k) const {
    return mesh.empty() ? static_cast<double>(k) / segments : mesh[static_cast<size_t>(k)];
  }
  /// h_k / T.
  double segmentFraction(int k) const { return fraction(k + 1) - fraction(k); }
  /// Time of point p from the start of the phase, for T = `total`.
  double time(int p, double total) const;
  double time(int p) const { return time(p, duration); }
  /// Weights w_p with sum_p w_p f(t_p) = the scheme's quadrature of the integral of f, for
  /// T = 1 (scale by T).
  Eigen::VectorXd quadratureWeights() const;
  /// @throws std::invalid_argument unless the mesh is empty or segments + 1 increasing
  /// fractions from 0 to 1.
  void validate() const;
  /// The variables of point p, [x, xdot, u, z].
  Eigen::VectorXd point(const Eigen::VectorXd& decision, int p) const {
    return decision.segment(pointOffset(p), pointSize());
  }
};

/// The collocation defects of one phase. With a fixed duration they are linear (constant
/// Jacobian, empty Hessian); with a free T they are bilinear in T and xdot.
class CollocationDefects : public ConstraintSet {
 public:
  /// @param phase  the phase the layout's points belong to (ConstraintSet)
  CollocationDefects(std::string name, std::string phase, const PhaseLayout& layout);
  void values(const Eigen::VectorXd& x, Eigen::Ref<Eigen::VectorXd> g) const override;
  void jacobian(const Eigen::VectorXd& x, Triplets& out) const override;
  void hessian(const Eigen::VectorXd& x, const Eigen::VectorXd& lambda,
               Triplets& out) const override;
  /// The segment of a row: nx rows per segment (trapezoidal), 2 nx (Hermite-Simpson).
  GridNode nodeOf(int row) const override {
    const int per_segment = layout_.pointsPerSegment() * layout_.nx;
    return {"segment", row / per_segment, row % per_segment};
  }

 private:
  PhaseLayout layout_;
  Triplets states_;  // coefficients of x: independent of T
  Triplets scaled_;  // coefficients of xdot per unit T: the entry is T * value
};

}  // namespace gaitopt::ocp
