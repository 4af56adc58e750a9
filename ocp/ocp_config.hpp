#pragma once
/// @file ocp_config.hpp
/// configs/ocp/*.yaml: which robot, which phases, the mesh and scheme, the cost, the constraint
/// switches and the solver options (DESIGN.md sec. 4 and 6). Paths are relative to the file.
#include <string>
#include <vector>

#include "ocp/collocation.hpp"
#include "ocp/ipopt_adapter.hpp"

namespace gaitopt::ocp {

struct PhaseConfig {
  std::string name;  ///< "SSP", then optionally "DSP"
  double duration = 0;
  int segments = 0;
};

/// Touchdown: rigid single impact (B lifts off; SSP-only steps), rigid double impact (both tips
/// stay; leads into a DSP), or impactless (zero swing-tip velocity at touchdown, Mu ch. 3).
enum class ImpactModel { kSingle, kDouble, kImpactless };

struct OcpConfig {
  std::string name;
  std::string robot_path;
  std::string guess_gait_path;  ///< polynomial gait used as the initial guess
  double step_length = 0;       ///< tips apart at touchdown [m]
  std::vector<PhaseConfig> phases;
  Scheme scheme = Scheme::kHermiteSimpson;
  ImpactModel impact = ImpactModel::kSingle;
  std::string cost = "torque_squared";  ///< "torque_squared" or "abs_work" (with slacks)
  double torque_regularization = 1e-3;  ///< weight of the torque-squared term added to abs_work
  // Constraint switches and bounds.
  bool torque_limits = true;   ///< |tau_j| <= robot torque limit; unactuated joints at 0
  bool knee_limits = true;     ///< knees never hyperextend (stance q1 >= 0, swing <= 0)
  double angle_range = 0;      ///< |theta - upright| bound per link [rad] (0: off)
  double rate_limit = 0;       ///< |dtheta| bound [rad/s] (0: off)
  bool swing_descends = true;  ///< swing tip vertical velocity <= 0 at strike
  bool trailing_lifts = true;  ///< old stance tip vertical velocity >= 0 after a single impact
  bool ground_contact = true;  ///< unilateral forces and friction cones at the tips in contact
  bool zmp = true;             ///< ZMP inside the support (only if the ankle is actuated)
  double clearance = -1;       ///< swing tip height >= clearance in the SSP [m] (< 0: off)
  SolverOptions solver;
};

/// @throws config::ConfigError naming file, key and expectation.
OcpConfig loadOcpConfig(const std::string& path);

}  // namespace gaitopt::ocp
