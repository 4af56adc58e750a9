#pragma once
/// @file straight_leg_guess.hpp
/// The initial guess of robots with straight legs (one link per leg: the compass gait, the
/// three-link walker), which the polynomial gait of Mu ch. 3 cannot serve (it needs knees): the
/// touchdown posture with the tips step_length apart, its relabelled image (Mu 2.38) as the start
/// posture, and a straight line in the link angles between them over the single support phase,
/// with the torques of the SSP inverse dynamics (Mu 2.43) along it. Its rates do not survive the
/// impact; the optimiser makes them. Scuffing is not modelled: with equal straight legs the swing
/// tip passes through y = 0 at mid-stance, as in every compass-gait study (McGeer 1990, Goswami
/// et al. 1998).
#include "dynamics/model.hpp"
#include "gaits/trajectory/trajectory.hpp"
#include "ocp/problem/ocp_config.hpp"

namespace gaitopt::ocp {

/// Link angles at touchdown: the stance leg leaning forward by asin(L / (2 l)), the swing leg
/// its mirror image about the hip's vertical, the torso (if any) upright in the world (theta =
/// slope in the ground frame). @throws std::domain_error when the legs cannot span the step.
VecD straightLegTouchdown(const dynamics::Model& model, double step_length);

/// The straight-line guess over the config's SSP (a step without DSP), sampled at 1 kHz.
/// @throws std::invalid_argument for a robot with knees or a config with a DSP,
///         std::domain_error for a step the legs cannot span.
gaits::Trajectory straightLegGuess(const dynamics::Model& model, const OcpConfig& config);

}  // namespace gaitopt::ocp
