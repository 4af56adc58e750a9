#pragma once
/// @file continuation_path.hpp
/// The problems a continuation passes through (continuation.hpp), one per value of a progress
/// p in [0, 1]: at p = 0 the easy problem, at p = 1 the configured one. The easy problem has the
/// configured variables, rows and mesh, so that each stage starts from the previous stage's
/// primal-dual solution; only bounds and weights move, by group (ContinuationOptions::parameters;
/// a group not listed keeps its configured values):
///   margins  friction_margin, zmp_margin  from 0 (the robot's whole cone and foot);
///   strike   touchdown.normal_velocity    its min from 0 (a strike may land at rest), max kept;
///   cost     the cost weights             torque_squared kept, every other weight from
///                                         cost_start times its configured value.
/// A parameter whose two ends are positive moves geometrically with p when the options say so
/// (ContinuationOptions::geometric), every other linearly.
#include <vector>

#include "ocp/problem/ocp_config.hpp"

namespace gaitopt::ocp {

/// The values a continuation moves, at one progress.
struct PathParameters {
  double friction_margin = 0;
  double impulse_friction_margin = 0;  ///< the impulses' (OcpConfig::impulse_friction_margin)
  double zmp_margin = 0;
  double min_normal_force = 0;                              ///< [N]
  double normal_velocity_min = 0, normal_velocity_max = 0;  ///< strike design only [m/s]
  CostWeights cost;
};

/// `target` at progress p (clamped to [0, 1]); exactly `target` at p = 1.
OcpConfig configAt(const OcpConfig& target, double progress);

PathParameters pathParameters(const OcpConfig& config);

/// Whether the path moves any parameter of `target` (else its easy problem is `target` itself).
bool pathMoves(const OcpConfig& target);

/// `config` on `segments` equal segments per phase (SSP, then DSP).
OcpConfig onSegments(OcpConfig config, const std::vector<int>& segments);

}  // namespace gaitopt::ocp
