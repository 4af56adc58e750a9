#pragma once
/// @file gait_problem.hpp
/// The periodic gait as one NLP (docs/design.md#the-optimal-control-problem): a single-support
/// phase collocated with the pinned-chain dynamics (Mu 2.7), the touchdown at its end (rigid single
/// or double impact with the impulses as variables, or impactless), optionally a double-support
/// phase with both tips pinned and the tip force as a variable (2.11), and relabelling (2.38) back
/// to the start. The initial guess is the polynomial gait of Mu ch. 3 sampled on the mesh.
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "dynamics/model.hpp"
#include "gaits/trajectory/trajectory.hpp"
#include "ocp/problem/ocp_config.hpp"
#include "ocp/problem/touchdown.hpp"
#include "ocp/transcription/collocation.hpp"
#include "ocp/transcription/nlp.hpp"
#include "ocp/transcription/phase.hpp"

namespace gaitopt::ocp {

struct GaitProblem {
  Nlp nlp;
  Phase ssp;
  std::optional<Phase> dsp;
  Touchdown touchdown;
  double step_length = 0;

  /// The phases in time order (SSP, then the DSP if any).
  std::vector<const Phase*> phases() const {
    std::vector<const Phase*> all{&ssp};
    if (dsp) all.push_back(&*dsp);
    return all;
  }
};

/// @throws std::invalid_argument when the guess does not fit the robot.
GaitProblem buildGaitProblem(const dynamics::Model& model, const OcpConfig& config,
                             const gaits::Trajectory& guess);

/// The solution as a Trajectory: one knot per collocation point (state, accelerations,
/// torques, tip forces), with the touchdown as an SSP -> DSP switch pair.
gaits::Trajectory reconstruct(const GaitProblem& problem, const dynamics::Model& model,
                              const Eigen::VectorXd& x);

/// The solution sampled at `rate_hz` (plus each phase's ends) from the collocation scheme's
/// own interpolating polynomials (collocation_interpolation.hpp): the export a controller gets.
gaits::Trajectory reconstructDense(const GaitProblem& problem, const dynamics::Model& model,
                                   const Eigen::VectorXd& x, double rate_hz);

}  // namespace gaitopt::ocp
