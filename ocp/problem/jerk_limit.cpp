#include "ocp/problem/jerk_limit.hpp"

#include <limits>
#include <utility>

namespace gaitopt::ocp {

JerkLimit::JerkLimit(std::string name, const Phase& phase, double jerk)
    : ConstraintSet(std::move(name), 2 * phase.point.n * (phase.layout.points() - 1), phase.name()),
      phase_(phase),
      jerk_(jerk) {}

Eigen::VectorXd JerkLimit::lowerBounds() const {
  Eigen::VectorXd lo = Eigen::VectorXd::Zero(rows());
  for (int r = 0; r < rows(); r += 2) lo(r) = -std::numeric_limits<double>::infinity();
  return lo;
}

Eigen::VectorXd JerkLimit::upperBounds() const {
  Eigen::VectorXd hi = Eigen::VectorXd::Zero(rows());
  for (int r = 1; r < rows(); r += 2) hi(r) = std::numeric_limits<double>::infinity();
  return hi;
}

void JerkLimit::values(const Eigen::VectorXd& x, Eigen::Ref<Eigen::VectorXd> g) const {
  const double duration = phase_.layout.durationAt(x);
  const Slice& a = phase_.point.a;
  int r = 0;
  for (int p = 0; p + 1 < phase_.layout.points(); ++p) {
    const double allowed = jerk_ * spacing(p) * duration;
    const Eigen::VectorXd change =
        a.of(phase_.layout.point(x, p + 1)) - a.of(phase_.layout.point(x, p));
    for (int j = 0; j < a.size; ++j) {
      g(r++) = change(j) - allowed;
      g(r++) = change(j) + allowed;
    }
  }
}

void JerkLimit::jacobian(const Eigen::VectorXd&, Triplets& out) const {
  const int t = phase_.layout.duration_index;
  int r = 0;
  for (int p = 0; p + 1 < phase_.layout.points(); ++p) {
    const std::vector<int> from = phase_.indices(p, phase_.point.a);
    const std::vector<int> to = phase_.indices(p + 1, phase_.point.a);
    const double allowed = jerk_ * spacing(p);
    for (size_t j = 0; j < from.size(); ++j)
      for (const double sign : {-1.0, 1.0}) {
        out.emplace_back(r, to[j], 1.0);
        out.emplace_back(r, from[j], -1.0);
        if (t >= 0) out.emplace_back(r, t, sign * allowed);
        ++r;
      }
  }
}

}  // namespace gaitopt::ocp
