#include "ocp/problem/jerk_jump.hpp"

#include <utility>
#include <vector>

namespace gaitopt::ocp {
namespace {

// The end slopes of each scheme's acceleration polynomial (collocation_interpolation.hpp), per
// unit T: Hermite-Simpson's quadratic through (0, a0), (h/2, am), (h, a1) has slope
// (-3 a0 + 4 am - a1) / h at its start and (a0 - 4 am + 3 a1) / h at its end; the trapezoidal
// line (a1 - a0) / h at both. The stencil of node k is the right segment's start slope minus the
// left one's end slope.
PointStencil nodeStencil(const PhaseLayout& layout, int node) {
  const double left = layout.segmentFraction(node - 1);
  const double right = layout.segmentFraction(node);
  if (layout.scheme == Scheme::kHermiteSimpson) {
    const int p = 2 * node;
    return {{p - 2, p - 1, p, p + 1, p + 2},
            {-1 / left, 4 / left, -3 / left - 3 / right, 4 / right, -1 / right}};
  }
  return {{node - 1, node, node + 1}, {1 / left, -1 / left - 1 / right, 1 / right}};
}

std::vector<PointStencil> interiorNodes(const PhaseLayout& layout) {
  std::vector<PointStencil> stencils;
  for (int node = 1; node < layout.segments; ++node) stencils.push_back(nodeStencil(layout, node));
  return stencils;
}

}  // namespace

JerkJump::JerkJump(std::string name, const Phase& phase, double jump)
    : PointStencilBound(std::move(name), phase, jump, interiorNodes(phase.layout),
                        &PointLayout::a) {}

}  // namespace gaitopt::ocp
