#pragma once
/// @file urdf_export.hpp
/// The planar robot as a URDF (ROS URDF XML specification, wiki.ros.org/urdf/XML) that DART,
/// Drake, Pinocchio and ROS tools load.
///
/// Frames: the walking plane is the URDF x-z plane (x forward, z up) and every joint turns about
/// y. A rotation by +a about +y takes z toward +x, so an absolute angle theta_i of
/// conventions.hpp (clockwise from the vertical, toward +x) is a rotation by theta_i about +y.
/// Link i's frame sits at its proximal joint with z along the link toward its distal end
/// (u_i of Mu 2.1); its CoM lies at (0, 0, d_i).
///
/// Joints: the model's joint j (j >= 1, between links j-1 and j) turns about -y, so that its
/// position is q_j = theta_{j-1} - theta_j of Mu (2.41). It sits at the distal end of link j-1,
/// or at its proximal joint when link j-1 is the torso (a_i = 0). Joints are URDF "continuous"
/// (revolute without position limits: the model bounds torque and rate, not angle), with
/// effort = torque_limit (0 when unactuated) and velocity = velocity_limit.
///
/// Feet: the root link `stance_foot` carries the stance ankle (joint 0, about +y: its position is
/// theta_0 minus the foot's angle, q_0 of Mu 2.41 when the foot is flat); the swing shank's
/// distal end carries `swing_ankle` (the limits of joint 0, which it becomes after relabelling,
/// Mu 2.38) and `swing_foot`, turned by pi so that both ankles measure the shank from the foot
/// the same way. A foot with heel or toe is a box from -heel to +toe along x; point feet (heel =
/// toe = 0) are spheres centred on the tip. Either sole lies below the tip (FootBody).
///
/// Root: `stance_foot` has no parent joint. A loader makes it planar (DART: PlanarJoint in the
/// XZ plane; Pinocchio: JointModelPlanar) or welds it to the ground for the stance-pinned chain
/// of Mu (2.7) (DART: DartLoader RootJointType::FIXED). Gravity and friction stay in the robot
/// file.
#include <string>

#include "dynamics/model.hpp"

namespace gaitopt::dynamics {

/// What the planar model lacks and the URDF needs: the feet as bodies [kg, m].
struct FootBody {
  double mass;       ///< each foot
  double thickness;  ///< box feet: the sole lies this far below the tip
  double width;      ///< box feet: extent across the walking plane (y)
  double radius;     ///< point feet: sphere radius, centred on the tip
};

/// The feet `gaitopt export-urdf` writes: 50 g each, about 0.2% of the lightest shipped robot
/// (10 kg), so that the walk's dynamics stay the model's; a 2 cm sole. A point foot's ball has a
/// 5 mm radius: a ball fixed to the shank rolls its centre r per radian the shank turns (2.2 mm
/// per RABBIT step in DART, 8.7 mm with r = 2 cm, near the 1 cm slip limit of a walk).
inline constexpr FootBody kExportFoot{
    .mass = 0.05, .thickness = 0.02, .width = 0.1, .radius = 0.005};

/// Link names the URDF adds to the model's.
inline constexpr const char* kStanceFootLink = "stance_foot";
inline constexpr const char* kSwingFootLink = "swing_foot";
/// Joint name the URDF adds to the model's.
inline constexpr const char* kSwingAnkleJoint = "swing_ankle";

/// The URDF text of `model` with `foot` bodies.
/// @throws std::invalid_argument when a link or joint name is empty, repeated (the added names
///         included) or holds a control character.
std::string urdfText(const Model& model, const FootBody& foot);

}  // namespace gaitopt::dynamics
