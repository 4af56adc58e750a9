#include "ocp/problem/jerk_jump.hpp"

#include <limits>
#include <utility>
#include <vector>

namespace gaitopt::ocp {

JerkJump::JerkJump(std::string name, const Phase& phase, double jump)
    : ConstraintSet(std::move(name), 2 * phase.point.n * (phase.layout.segments - 1), phase.name()),
      phase_(phase),
      jump_(jump) {}

Eigen::VectorXd JerkJump::lowerBounds() const {
  Eigen::VectorXd lo = Eigen::VectorXd::Zero(rows());
  for (int r = 0; r < rows(); r += 2) lo(r) = -std::numeric_limits<double>::infinity();
  return lo;
}

Eigen::VectorXd JerkJump::upperBounds() const {
  Eigen::VectorXd hi = Eigen::VectorXd::Zero(rows());
  for (int r = 1; r < rows(); r += 2) hi(r) = std::numeric_limits<double>::infinity();
  return hi;
}

// The end slopes of each scheme's acceleration polynomial (collocation_interpolation.hpp), per
// unit T: Hermite-Simpson's quadratic through (0, a0), (h/2, am), (h, a1) has slope
// (-3 a0 + 4 am - a1) / h at its start and (a0 - 4 am + 3 a1) / h at its end; the trapezoidal
// line (a1 - a0) / h at both.
JerkJump::Stencil JerkJump::stencil(int node) const {
  const PhaseLayout& layout = phase_.layout;
  const double left = layout.segmentFraction(node - 1);
  const double right = layout.segmentFraction(node);
  Stencil s;
  if (layout.scheme == Scheme::kHermiteSimpson) {
    const int p = 2 * node;
    s.points = {p - 2, p - 1, p, p + 1, p + 2};
    s.weights = {-1 / left, 4 / left, -3 / left - 3 / right, 4 / right, -1 / right};
    s.size = 5;
  } else {
    s.points = {node - 1, node, node + 1, 0, 0};
    s.weights = {1 / left, -1 / left - 1 / right, 1 / right, 0, 0};
    s.size = 3;
  }
  return s;
}

void JerkJump::values(const Eigen::VectorXd& x, Eigen::Ref<Eigen::VectorXd> g) const {
  const double allowed = jump_ * phase_.layout.durationAt(x);
  const Slice& a = phase_.point.a;
  int r = 0;
  for (int node = 1; node < phase_.layout.segments; ++node) {
    const Stencil s = stencil(node);
    Eigen::VectorXd scaled = Eigen::VectorXd::Zero(a.size);
    for (int i = 0; i < s.size; ++i)
      scaled += s.weights[i] * a.of(phase_.layout.point(x, s.points[i]));
    for (int j = 0; j < a.size; ++j) {
      g(r++) = scaled(j) - allowed;
      g(r++) = scaled(j) + allowed;
    }
  }
}

void JerkJump::jacobian(const Eigen::VectorXd&, Triplets& out) const {
  const int t = phase_.layout.duration_index;
  int r = 0;
  for (int node = 1; node < phase_.layout.segments; ++node) {
    const Stencil s = stencil(node);
    std::vector<std::vector<int>> columns;
    for (int i = 0; i < s.size; ++i) columns.push_back(phase_.indices(s.points[i], phase_.point.a));
    for (int j = 0; j < phase_.point.a.size; ++j)
      for (const double sign : {-1.0, 1.0}) {
        for (int i = 0; i < s.size; ++i) out.emplace_back(r, columns[i][j], s.weights[i]);
        if (t >= 0) out.emplace_back(r, t, sign * jump_);
        ++r;
      }
  }
}

}  // namespace gaitopt::ocp
