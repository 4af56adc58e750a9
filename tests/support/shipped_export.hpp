#pragma once
/// @file shipped_export.hpp
/// A shipped OCP config solved as `gaitopt optimize` solves it (ocp::solveGait, its continuation
/// included) from its polynomial guess, and its 1 kHz export: the reference a walk test follows.
#include <string>

#include "dynamics/robot_files/robot_config.hpp"
#include "ocp/guess/initial_guess.hpp"
#include "ocp/solve/gait_solve.hpp"
#include "solved_config.hpp"

namespace gaitopt::test {

struct ShippedExport {
  dynamics::Model model;    ///< the config's robot
  gaits::Trajectory dense;  ///< the optimum at 1 kHz
  std::string status;       ///< Ipopt's
  bool success = false;
};

/// configs/ocp/NAME.yaml solved and exported.
inline ShippedExport shippedExport(const std::string& name) {
  const auto config = ocp::loadOcpConfig(shippedOcpConfig(name));
  ShippedExport e{dynamics::loadRobot(config.robot_path), {}, {}, false};
  const auto solution = ocp::solveGait(e.model, config, ocp::polynomialGuess(e.model, config));
  e.status = solution.result.status;
  e.success = solution.result.success;
  if (e.success)
    e.dense = ocp::reconstructDense(solution.problem, e.model, solution.result.x, 1000.0);
  return e;
}

}  // namespace gaitopt::test
