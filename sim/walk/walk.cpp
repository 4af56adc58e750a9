#include "sim/walk/walk.hpp"

#include <type_traits>

#include "sim/contact/compliant_walk.hpp"
#include "sim/contact/dart_walk.hpp"
#include "sim/contact/lcp_walk.hpp"

namespace gaitopt::sim {

std::string groundName(const GroundModel& ground) {
  return std::visit(
      [](const auto& g) -> std::string {
        using G = std::decay_t<decltype(g)>;
        if constexpr (std::is_same_v<G, RigidGround>) return "rigid";
        if constexpr (std::is_same_v<G, CompliantGround>) return "impedance";
        if constexpr (std::is_same_v<G, LcpGround>) return "lcp";
        return "dart";
      },
      ground);
}

WalkResult walk(const dynamics::Model& plant, const Controller& controller, const Reference& ref,
                const GroundModel& ground, const WalkPlan& plan, const WalkLog& log,
                const VecD& theta0, const VecD& dtheta0) {
  return std::visit(
      [&](const auto& g) {
        using G = std::decay_t<decltype(g)>;
        if constexpr (std::is_same_v<G, RigidGround>)
          return simulateWalk(plant, controller, ref, WalkOptions{plan, g.integrator}, log, theta0,
                              dtheta0);
        else if constexpr (std::is_same_v<G, CompliantGround>)
          return walkCompliant(plant, controller, ref, g, plan, log, theta0, dtheta0);
        else if constexpr (std::is_same_v<G, LcpGround>)
          return walkLcp(plant, controller, ref, g, plan, log, theta0, dtheta0);
        else
          return walkDart(plant, controller, ref, g, plan, log, theta0, dtheta0);
      },
      ground);
}

}  // namespace gaitopt::sim
