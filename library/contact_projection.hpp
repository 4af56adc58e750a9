#pragma once
/// @file contact_projection.hpp
/// A blend of solved gaits (interpolation.hpp) put back on its contacts. Angles blended with the
/// corners' weights keep no tip where it must be: the tip position is not linear in the angles,
/// so in the double support the leading tip, pinned in every corner, moves (0.05 mm on a blend of
/// the throughput library, 1.1 mm across slopes), and the single support ends with the swing tip
/// above the ground. Followed by a controller, such a step falls in its first touchdown. Here:
///  - every double-support knot is projected onto the pinned chain (Mu 2.11): the angles by
///    Gauss-Newton onto E(theta) = (L, 0), the rates onto J dtheta = 0 and the accelerations onto
///    J ddtheta + Jdot dtheta = 0, each the least change (J^T (J J^T)^-1);
///  - the single support is bent by a quintic that moves its last knot onto the projected
///    touchdown posture, landing at the corners' tip velocity, and its first onto the relabelled
///    end of the double support (Mu 2.38), with zero change of acceleration at both ends, so the
///    step stays periodic.
/// The changes are of the order of the blend's own error, which falls with the square of the grid
/// spacing (interpolation_test.cpp).
#include <vector>

#include "dynamics/model.hpp"
#include "gaits/trajectory/trajectory.hpp"

namespace gaitopt::library {

/// Moves `knots` (one step: SSP knots, then DSP knots if the step has a double support, a switch
/// pair at the touchdown) onto the contacts of a step of `step_length` [m], the swing tip landing
/// at `touchdown_velocity` [m/s] (the corners' blended: at rest for gaits that land at rest). A
/// step without a double support (it ends in an impact, which a blend does not keep) only has its
/// touchdown moved. Torques and forces are left to the caller (inverse dynamics of the result).
/// @throws std::runtime_error when a posture cannot reach the step (the projection does not
///         converge).
void holdBlendContacts(std::vector<gaits::Knot>& knots, const dynamics::Model& model,
                       double step_length, const Vec2d& touchdown_velocity);

}  // namespace gaitopt::library
