#pragma once
/// @file state_file.hpp
/// The chain state a subcommand evaluates: absolute angles, rates and accelerations
/// (conventions.hpp), either read from a JSON state file or a default standing posture.
#include <string>

#include "dynamics/conventions.hpp"
#include "dynamics/model.hpp"

namespace gaitopt::gaits {

/// theta [rad], dtheta [rad/s], ddtheta [rad/s^2], each of length Model::nLinks().
struct ChainState {
  VecD theta;
  VecD dtheta;
  VecD ddtheta;
};

/// Standing upright at rest: stance-leg links and torso at theta = 0, swing-leg links at
/// theta = pi (straight leg hanging down from the hip), zero rates and accelerations.
ChainState standingState(const dynamics::Model& model);

/// Reads `{"theta": [...], "dtheta": [...], "ddtheta": [...]}`; theta is required, the others
/// default to zero. Each must hold `n_links` numbers in the ranges of config/quantities.hpp; no
/// other key is allowed.
/// @throws config::ConfigError naming the file, the key and what was expected.
ChainState loadState(const std::string& path, int n_links);

}  // namespace gaitopt::gaits
