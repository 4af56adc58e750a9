#pragma once
/// @file physical_joints.hpp
/// Joint coordinates as a robot's joint encoders have them (docs/design.md#the-export-contract):
/// per leg, the ankle, knee and hip with one sign convention in both legs, where Mu's q (2.41)
/// measures the swing leg's joints with the opposite sign (stance knee q1 >= 0, swing knee q4 <= 0)
/// and its hip against the torso's upward direction (q3 near -pi).
///
/// Convention: a link's "down angle" is its direction from its upper joint toward the ground,
/// from the downward vertical, > 0 pointing forward; the torso's is minus its lean. Then
///   hip  = thigh down angle - torso down angle  (flexion > 0: thigh forward of the torso line),
///   knee = thigh down angle - shank down angle  (flexion > 0: shank behind the thigh),
///   ankle = the stance shank's angle from the vertical (Mu's q0; the stance foot is flat).
/// Without a torso (compass gait) the hip is the swing thigh's angle from the stance leg's
/// line. "left" is the leg in stance during this step, "right" the swing leg; the next step
/// swaps them (Mu 2.38 relabels the links, not the legs).
///
/// Each physical coordinate is +-q_j (+ pi), so its rate is +-dq_j and the torque that does
/// work on it is +-tau_j.
#include <string>
#include <vector>

#include "dynamics/model.hpp"

namespace gaitopt::gaits {

struct PhysicalJoint {
  std::string name;  ///< e.g. "left_knee"
  int q = 0;         ///< Mu's joint index j (q_j, tau_j)
  double sign = 1;   ///< physical = sign q_j + offset
  double offset = 0;
};

/// The physical joints of `model`, in chain order (left ankle, knee, hip, then right hip,
/// knee). @throws std::invalid_argument for a chain that is not stance leg, [torso,] swing leg.
std::vector<PhysicalJoint> physicalJoints(const dynamics::Model& model);

/// The physical coordinates of joint values q (angles: with offsets; rates and torques:
/// `with_offset` false).
Eigen::VectorXd physicalValues(const std::vector<PhysicalJoint>& joints, const VecD& q,
                               bool with_offset);

}  // namespace gaitopt::gaits
