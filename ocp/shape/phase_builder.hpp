#pragma once
/// @file phase_builder.hpp
/// One phase of the shape (gait_shape.hpp) in the NLP: its variables (a free duration unless it
/// shares another phase's, then its collocation points, guessed from a gait) and its own sets:
/// the collocation defects (or the DSP on its chart, dsp_chart.hpp), the dynamics as a path
/// constraint, the limits, ground contact, clearance, and the running cost.
#include <optional>

#include "dynamics/model.hpp"
#include "gaits/trajectory/trajectory.hpp"
#include "ocp/problem/ocp_config.hpp"
#include "ocp/shape/gait_shape.hpp"
#include "ocp/transcription/nlp.hpp"
#include "ocp/transcription/phase.hpp"

namespace gaitopt::ocp {

/// Adds the variables of `spec` on `model`, its points from `guess` (the step's SSP, then its
/// DSP from the guess's switch on). `shared_duration`: the variable index (or -1 for a fixed
/// duration) of the phase whose clock this one runs on; nullopt for its own.
Phase addPhaseVariables(Nlp& nlp, const dynamics::Model& model, const OcpConfig& config,
                        const gaits::Trajectory& guess, const PhaseSpec& spec,
                        std::optional<int> shared_duration);

/// Adds the phase's own constraint sets and, with `cost`, its running cost terms (and the work
/// slacks' rows that an absolute-work cost needs).
void addPhaseSets(Nlp& nlp, const dynamics::Model& model, const OcpConfig& config,
                  const Phase& phase, bool cost);

}  // namespace gaitopt::ocp
