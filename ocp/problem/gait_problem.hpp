#pragma once
/// @file gait_problem.hpp
/// The periodic gait as one NLP (docs/design.md#the-optimal-control-problem): a single-support
/// phase collocated with the pinned-chain dynamics (Mu 2.7), the touchdown at its end (rigid single
/// or double impact with the impulses as variables, or impactless), optionally a double-support
/// phase with both tips pinned and the tip force as a variable (2.11), and relabelling (2.38) back
/// to the start; repeated for several steps and model variants when the config asks for them
/// (docs/design.md#the-problems-shape). The initial guess is the polynomial gait of Mu ch. 3
/// sampled on the mesh.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "dynamics/model.hpp"
#include "gaits/trajectory/trajectory.hpp"
#include "ocp/problem/ocp_config.hpp"
#include "ocp/problem/touchdown.hpp"
#include "ocp/shape/stage_structure.hpp"
#include "ocp/transcription/collocation.hpp"
#include "ocp/transcription/nlp.hpp"
#include "ocp/transcription/phase.hpp"

namespace gaitopt::ocp {

/// One phase as built: where its variables sit, which step and variant it is, its model and,
/// for a single support, the touchdown at its end.
struct BuiltPhase {
  Phase phase;
  int step = 0;
  int variant = 0;
  const dynamics::Model* model = nullptr;
  std::optional<Touchdown> touchdown;
};

struct GaitProblem {
  Nlp nlp;
  Phase ssp;                 ///< the nominal's first step
  std::optional<Phase> dsp;  ///< the nominal's first step
  Touchdown touchdown;       ///< the nominal's first step
  double step_length = 0;    ///< the nominal's
  /// Per variant, the step its tips are pinned to: the nominal's times the copy's length_scale.
  std::vector<double> step_lengths;
  int steps = 1;
  int variants = 1;
  std::vector<BuiltPhase> built;  ///< every phase of every step and variant, in build order
  StageStructure stages;          ///< the stages of the NLP and their couplings
  /// The variants' models, which the sets point to ([0], the caller's, is not owned).
  std::vector<std::shared_ptr<const dynamics::Model>> models;
  /// The models the variants' computed-torque laws compute with (GaitShape::controllers).
  std::vector<std::shared_ptr<const dynamics::Model>> controllers;

  /// The nominal's first step in time order (SSP, then the DSP if any).
  std::vector<const Phase*> phases() const {
    std::vector<const Phase*> all{&ssp};
    if (dsp) all.push_back(&*dsp);
    return all;
  }
  /// Step `step` of variant `variant` in time order. @throws std::out_of_range when absent.
  std::vector<const Phase*> phasesOf(int step, int variant) const;
  /// The step of variant `variant`. @throws std::out_of_range when absent.
  double stepLengthOf(int variant) const { return step_lengths.at(static_cast<size_t>(variant)); }
};

/// The shape of `config` (gait_shape.hpp) assembled by the one builder (shape_builder.hpp), every
/// step and variant from `guess`.
/// @throws std::invalid_argument when the guess does not fit the robot.
GaitProblem buildGaitProblem(const dynamics::Model& model, const OcpConfig& config,
                             const gaits::Trajectory& guess);

/// Step `step` of variant `variant` of the solution as a Trajectory: one knot per collocation
/// point (state, accelerations, torques, tip forces), with the touchdown as an SSP -> DSP switch
/// pair. A Trajectory is one step in its stance tip's frame, so the steps of a longer period
/// are one Trajectory each (reconstructSteps). `model` is the nominal; a variant is
/// reconstructed on its own.
gaits::Trajectory reconstruct(const GaitProblem& problem, const dynamics::Model& model,
                              const Eigen::VectorXd& x, int step = 0, int variant = 0);

/// Every step of the nominal in order (reconstruct).
std::vector<gaits::Trajectory> reconstructSteps(const GaitProblem& problem,
                                                const dynamics::Model& model,
                                                const Eigen::VectorXd& x);

/// The solution sampled at `rate_hz` (plus each phase's ends) from the collocation scheme's
/// own interpolating polynomials (collocation_interpolation.hpp): the export a controller gets.
gaits::Trajectory reconstructDense(const GaitProblem& problem, const dynamics::Model& model,
                                   const Eigen::VectorXd& x, double rate_hz, int step = 0,
                                   int variant = 0);

}  // namespace gaitopt::ocp
