#pragma once
/// @file initial_guess.hpp
/// The initial guess a gait problem starts from (DESIGN.md sec. 6): the polynomial gait of Mu
/// ch. 3 named by the config, its free hip parameters chosen by NLopt (hip_plan_search.hpp),
/// sampled at 1 kHz.
#include "dynamics/model.hpp"
#include "gaits/trajectory.hpp"
#include "ocp/ocp_config.hpp"

namespace gaitopt::ocp {

/// @throws config::ConfigError for a bad gait file, std::domain_error for an unreachable gait.
gaits::Trajectory polynomialGuess(const dynamics::Model& model, const OcpConfig& config);

}  // namespace gaitopt::ocp
