#include "gaits/trajectory/physical_joints.hpp"

#include <numbers>
#include <stdexcept>

#include <fmt/format.h>

namespace gaitopt::gaits {

std::vector<PhysicalJoint> physicalJoints(const dynamics::Model& model) {
  const int n = model.nLinks(), legs = model.legLinks();
  const int torso = model.torso() ? 1 : 0;
  if (n != 2 * legs + torso || legs < 1 || legs > 2 || (torso && *model.torso() != legs))
    throw std::invalid_argument(fmt::format(
        "robot '{}': physical joints need the chain stance leg, [torso,] swing leg", model.name()));
  constexpr double kPi = std::numbers::pi;
  // Mu (2.41): q_j = theta_j - theta_{j+1}, links counted from the stance tip (1-based).
  std::vector<PhysicalJoint> joints{{"left_ankle", 0, 1.0, 0.0}};
  if (legs == 2) joints.push_back({"left_knee", 1, 1.0, 0.0});  // theta_shank - theta_thigh
  if (torso) {
    joints.push_back({"left_hip", legs, -1.0, 0.0});      // theta_torso - theta_thigh
    joints.push_back({"right_hip", legs + 1, 1.0, kPi});  // pi - theta_thigh + theta_torso
  } else {
    joints.push_back({"right_hip", legs, 1.0, kPi});  // the swing leg from the stance leg's line
  }
  if (legs == 2) joints.push_back({"right_knee", n - 1, -1.0, 0.0});  // theta_shank - theta_thigh
  return joints;
}

Eigen::VectorXd physicalValues(const std::vector<PhysicalJoint>& joints, const VecD& q,
                               bool with_offset) {
  Eigen::VectorXd out(static_cast<Eigen::Index>(joints.size()));
  for (size_t i = 0; i < joints.size(); ++i)
    out(static_cast<Eigen::Index>(i)) =
        joints[i].sign * q(joints[i].q) + (with_offset ? joints[i].offset : 0.0);
  return out;
}

}  // namespace gaitopt::gaits
