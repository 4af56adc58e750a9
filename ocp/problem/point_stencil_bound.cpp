#include "ocp/problem/point_stencil_bound.hpp"

#include <limits>
#include <utility>

namespace gaitopt::ocp {

std::vector<PointStencil> consecutivePointStencils(const PhaseLayout& layout) {
  std::vector<PointStencil> stencils;
  for (int p = 0; p + 1 < layout.points(); ++p)
    stencils.push_back({{p, p + 1}, {-1.0, 1.0}, layout.time(p + 1, 1.0) - layout.time(p, 1.0)});
  return stencils;
}

PointStencilBound::PointStencilBound(std::string name, const Phase& phase, double bound,
                                     std::vector<PointStencil> stencils, Slice PointLayout::*block)
    : ConstraintSet(std::move(name),
                    2 * (phase.point.*block).size * static_cast<int>(stencils.size()),
                    phase.name()),
      phase_(phase),
      block_(phase.point.*block),
      bound_(bound),
      stencils_(std::move(stencils)) {}

Eigen::VectorXd PointStencilBound::lowerBounds() const {
  Eigen::VectorXd lo = Eigen::VectorXd::Zero(rows());
  for (int r = 0; r < rows(); r += 2) lo(r) = -std::numeric_limits<double>::infinity();
  return lo;
}

Eigen::VectorXd PointStencilBound::upperBounds() const {
  Eigen::VectorXd hi = Eigen::VectorXd::Zero(rows());
  for (int r = 1; r < rows(); r += 2) hi(r) = std::numeric_limits<double>::infinity();
  return hi;
}

void PointStencilBound::values(const Eigen::VectorXd& x, Eigen::Ref<Eigen::VectorXd> g) const {
  const double duration = phase_.layout.durationAt(x);
  int r = 0;
  for (const PointStencil& s : stencils_) {
    const double allowed = bound_ * s.allowance * duration;
    Eigen::VectorXd sum = Eigen::VectorXd::Zero(block_.size);
    for (size_t i = 0; i < s.points.size(); ++i)
      sum += s.weights[i] * block_.of(phase_.layout.point(x, s.points[i]));
    for (int j = 0; j < block_.size; ++j) {
      g(r++) = sum(j) - allowed;
      g(r++) = sum(j) + allowed;
    }
  }
}

void PointStencilBound::jacobian(const Eigen::VectorXd&, Triplets& out) const {
  const int t = phase_.layout.duration_index;
  int r = 0;
  for (const PointStencil& s : stencils_) {
    std::vector<std::vector<int>> columns;
    for (const int p : s.points) columns.push_back(phase_.indices(p, block_));
    for (int j = 0; j < block_.size; ++j)
      for (const double sign : {-1.0, 1.0}) {
        for (size_t i = 0; i < s.points.size(); ++i)
          out.emplace_back(r, columns[i][static_cast<size_t>(j)], s.weights[i]);
        if (t >= 0) out.emplace_back(r, t, sign * bound_ * s.allowance);
        ++r;
      }
  }
}

}  // namespace gaitopt::ocp
