#include "ocp/problem/jerk_limit.hpp"

#include <utility>

namespace gaitopt::ocp {

JerkLimit::JerkLimit(std::string name, const Phase& phase, double jerk)
    : PointStencilBound(std::move(name), phase, jerk, consecutivePointStencils(phase.layout),
                        &PointLayout::a) {}

}  // namespace gaitopt::ocp
