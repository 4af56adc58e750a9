#include "ocp/problem/jerk_limit.hpp"

#include <utility>
#include <vector>

namespace gaitopt::ocp {
namespace {

std::vector<AccelerationStencil> consecutivePoints(const PhaseLayout& layout) {
  std::vector<AccelerationStencil> stencils;
  for (int p = 0; p + 1 < layout.points(); ++p)
    stencils.push_back({{p, p + 1}, {-1.0, 1.0}, layout.time(p + 1, 1.0) - layout.time(p, 1.0)});
  return stencils;
}

}  // namespace

JerkLimit::JerkLimit(std::string name, const Phase& phase, double jerk)
    : AccelerationStencilBound(std::move(name), phase, jerk, consecutivePoints(phase.layout)) {}

}  // namespace gaitopt::ocp
