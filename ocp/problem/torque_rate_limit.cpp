#include "ocp/problem/torque_rate_limit.hpp"

#include <utility>

namespace gaitopt::ocp {

TorqueRateLimit::TorqueRateLimit(std::string name, const Phase& phase, double rate)
    : PointStencilBound(std::move(name), phase, rate, consecutivePointStencils(phase.layout),
                        &PointLayout::u) {}

}  // namespace gaitopt::ocp
