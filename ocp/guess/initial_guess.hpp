#pragma once
/// @file initial_guess.hpp
/// The initial guess a gait problem starts from (docs/design.md#the-optimal-control-problem): the
/// polynomial gait of Mu ch. 3 named by the config, its free hip parameters chosen by NLopt
/// (hip_plan_search.hpp), sampled at 1 kHz; robots with straight legs start from
/// straight_leg_guess.hpp.
#include "dynamics/model.hpp"
#include "gaits/polynomial/gait_params.hpp"
#include "gaits/trajectory/trajectory.hpp"
#include "ocp/problem/ocp_config.hpp"

namespace gaitopt::ocp {

/// The gait is designed on `model` (normally problemModel(config)), so it carries the OCP's
/// slope; the gait file's own `slope` key is ignored here.
/// @throws config::ConfigError for a bad gait file, std::domain_error for an unreachable gait.
gaits::Trajectory polynomialGuess(const dynamics::Model& model, const OcpConfig& config);

/// The config's initial guess: its polynomial gait, or the straight-leg guess
/// (straight_leg_guess.hpp) for `initial_guess: straight_leg`.
/// @throws as polynomialGuess or straightLegGuess.
gaits::Trajectory initialGuess(const dynamics::Model& model, const OcpConfig& config);

/// The polynomial gait of `params` on `model` (a gait library point's own parameters).
/// @throws std::domain_error for an unreachable gait.
gaits::Trajectory polynomialGuess(const dynamics::Model& model, const gaits::GaitParams& params);

}  // namespace gaitopt::ocp
