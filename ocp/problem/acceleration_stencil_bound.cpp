#include "ocp/problem/acceleration_stencil_bound.hpp"

#include <limits>
#include <utility>

namespace gaitopt::ocp {

AccelerationStencilBound::AccelerationStencilBound(std::string name, const Phase& phase,
                                                   double bound,
                                                   std::vector<AccelerationStencil> stencils)
    : ConstraintSet(std::move(name), 2 * phase.point.n * static_cast<int>(stencils.size()),
                    phase.name()),
      phase_(phase),
      bound_(bound),
      stencils_(std::move(stencils)) {}

Eigen::VectorXd AccelerationStencilBound::lowerBounds() const {
  Eigen::VectorXd lo = Eigen::VectorXd::Zero(rows());
  for (int r = 0; r < rows(); r += 2) lo(r) = -std::numeric_limits<double>::infinity();
  return lo;
}

Eigen::VectorXd AccelerationStencilBound::upperBounds() const {
  Eigen::VectorXd hi = Eigen::VectorXd::Zero(rows());
  for (int r = 1; r < rows(); r += 2) hi(r) = std::numeric_limits<double>::infinity();
  return hi;
}

void AccelerationStencilBound::values(const Eigen::VectorXd& x,
                                      Eigen::Ref<Eigen::VectorXd> g) const {
  const double duration = phase_.layout.durationAt(x);
  const Slice& a = phase_.point.a;
  int r = 0;
  for (const AccelerationStencil& s : stencils_) {
    const double allowed = bound_ * s.allowance * duration;
    Eigen::VectorXd sum = Eigen::VectorXd::Zero(a.size);
    for (size_t i = 0; i < s.points.size(); ++i)
      sum += s.weights[i] * a.of(phase_.layout.point(x, s.points[i]));
    for (int j = 0; j < a.size; ++j) {
      g(r++) = sum(j) - allowed;
      g(r++) = sum(j) + allowed;
    }
  }
}

void AccelerationStencilBound::jacobian(const Eigen::VectorXd&, Triplets& out) const {
  const int t = phase_.layout.duration_index;
  int r = 0;
  for (const AccelerationStencil& s : stencils_) {
    std::vector<std::vector<int>> columns;
    for (const int p : s.points) columns.push_back(phase_.indices(p, phase_.point.a));
    for (int j = 0; j < phase_.point.a.size; ++j)
      for (const double sign : {-1.0, 1.0}) {
        for (size_t i = 0; i < s.points.size(); ++i)
          out.emplace_back(r, columns[i][static_cast<size_t>(j)], s.weights[i]);
        if (t >= 0) out.emplace_back(r, t, sign * bound_ * s.allowance);
        ++r;
      }
  }
}

}  // namespace gaitopt::ocp
