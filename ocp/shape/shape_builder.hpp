#pragma once
/// @file shape_builder.hpp
/// The one builder of gait problems: the flat NLP (nlp.hpp) assembled from a shape
/// (gait_shape.hpp), phase by phase in the shape's order, each phase followed by its touchdown
/// and by the transitions whose later phase it is; the stages it emits are recorded on the
/// problem (stage_structure.hpp).
#include <vector>

#include "gaits/trajectory/trajectory.hpp"
#include "ocp/problem/gait_problem.hpp"
#include "ocp/problem/ocp_config.hpp"
#include "ocp/shape/gait_shape.hpp"

namespace gaitopt::ocp {

/// `guesses`: one gait per step (a variant's step starts from the nominal's guess), or one for
/// every step. @throws std::invalid_argument when the guesses do not fit the shape's steps or
/// the robot.
GaitProblem assembleGaitProblem(const GaitShape& shape, const OcpConfig& config,
                                const std::vector<gaits::Trajectory>& guesses);

}  // namespace gaitopt::ocp
