#pragma once
/// @file push.hpp
/// An external push on the hip: a force pulse F = P / d over d seconds of single support,
/// starting at a given time of a given step, delivering the impulse P. A pulse rather than an
/// ideal impulse: with a pinned stance tip an ideal impulse needs an impulsive ground reaction,
/// which almost never lies inside the friction cone, so every push would be a slip on rigid
/// ground; a pulse of 0.1 s is what a shove or a collision with an obstacle lasts.
#include <optional>

#include "dynamics/model.hpp"

namespace gaitopt::sim {

struct Push {
  int step = 2;                   ///< 1-based step of the walk
  std::optional<double> time;     ///< start on the step clock [s]; default: mid single support
  Vec2d impulse = Vec2d::Zero();  ///< on the hip, world frame [N s]
  double duration = 0.1;          ///< of the pulse, > 0 [s]
};

/// An impulse the robot's weight delivers within this time is absorbed by finite contact forces
/// (friction on the weight), not by an impulsive one, so it is not checked against the friction
/// cone [s].
inline constexpr double kNegligibleImpulseTime = 1e-3;

/// When the push starts on the step clock, for a single support of `ssp_duration` [s].
double pushStart(const Push& push, double ssp_duration);

/// The force on the hip at step clock t of the single support of step `step_index` (0-based):
/// impulse / duration within [start, start + duration), zero elsewhere and in other steps [N].
Vec2d pushForce(const std::optional<Push>& push, int step_index, double t, double ssp_duration);

}  // namespace gaitopt::sim
