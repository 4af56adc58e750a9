#pragma once
/// @file collocation.hpp
/// Direct collocation of one phase, independent of the robot (Betts 2010; Kelly, SIAM Review
/// 2017). A phase of fixed duration is cut into equal segments; each collocation point carries
/// the state x, its time derivative xdot (so any dynamics enter as an implicit path constraint
/// F(x, xdot, u, z) = 0), inputs u and algebraic variables z (e.g. contact forces).
///   trapezoidal:     x_{k+1} - x_k - h/2 (xdot_k + xdot_{k+1}) = 0                 (order 2)
///   Hermite-Simpson, separated form (points 2k, 2k+1 = midpoint, 2k+2):
///     x_{2k+2} - x_{2k} - h/6 (xdot_{2k} + 4 xdot_{2k+1} + xdot_{2k+2}) = 0           (Simpson)
///     x_{2k+1} - (x_{2k} + x_{2k+2})/2 - h/8 (xdot_{2k} - xdot_{2k+2}) = 0         (order 4)
#include <string>

#include "ocp/nlp.hpp"

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
  double duration = 0;
  int nx = 0, nu = 0, nz = 0;
  int offset = 0;  ///< first variable of the phase in the decision vector
  int nq = 0;      ///< > 0: second-order form with nx = 2 nq

  int points() const { return scheme == Scheme::kHermiteSimpson ? 2 * segments + 1 : segments + 1; }
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
  double segmentLength() const { return duration / segments; }
  /// Time of point p from the start of the phase.
  double time(int p) const;
  /// Weights w_p with sum_p w_p f(t_p) = the scheme's quadrature of the integral of f.
  Eigen::VectorXd quadratureWeights() const;
  /// The variables of point p, [x, xdot, u, z].
  Eigen::VectorXd point(const Eigen::VectorXd& decision, int p) const {
    return decision.segment(pointOffset(p), pointSize());
  }
};

/// The collocation defects of one phase: linear in the variables (fixed duration), so the
/// Jacobian is constant and the Hessian empty.
class CollocationDefects : public ConstraintSet {
 public:
  explicit CollocationDefects(const PhaseLayout& layout, const std::string& name = "defects");
  void values(const Eigen::VectorXd& x, Eigen::Ref<Eigen::VectorXd> g) const override;
  void jacobian(const Eigen::VectorXd& x, Triplets& out) const override;
  void hessian(const Eigen::VectorXd&, const Eigen::VectorXd&, Triplets&) const override {}

 private:
  PhaseLayout layout_;
  Triplets entries_;  // constant Jacobian, built once
};

}  // namespace gaitopt::ocp
