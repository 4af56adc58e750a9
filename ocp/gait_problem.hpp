#pragma once
/// @file gait_problem.hpp
/// The periodic gait as one NLP (DESIGN.md sec. 6): a single-support phase collocated with the
/// pinned-chain dynamics, the heel-strike impact at its end (rigid, single or double, impulses
/// as variables), and relabelling back to the start of the phase. The initial guess is the
/// polynomial gait of Mu ch. 3 sampled on the mesh.
#include <Eigen/Core>

#include "dynamics/model.hpp"
#include "gaits/trajectory.hpp"
#include "ocp/collocation.hpp"
#include "ocp/nlp.hpp"
#include "ocp/ocp_config.hpp"

namespace gaitopt::ocp {

struct GaitProblem {
  Nlp nlp;
  PhaseLayout ssp;
  int impact_offset = 0;  ///< qdot+ (n + 2), P_E (2) [, P_B (2)]
  double step_length = 0;
};

/// @throws std::invalid_argument when the guess does not cover the phase.
GaitProblem buildGaitProblem(const dynamics::Model& model, const OcpConfig& config,
                             const gaits::Trajectory& guess);

/// The solution as a Trajectory: one knot per collocation point (state, accelerations,
/// torques, ground force at B from total momentum).
gaits::Trajectory reconstruct(const GaitProblem& problem, const dynamics::Model& model,
                              const Eigen::VectorXd& x);

}  // namespace gaitopt::ocp
