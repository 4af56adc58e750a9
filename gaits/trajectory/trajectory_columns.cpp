#include "gaits/trajectory/trajectory_columns.hpp"

#include <cmath>
#include <iterator>
#include <stdexcept>

#include <fmt/format.h>

#include "dynamics/joint_coordinates.hpp"
#include "dynamics/kinematics.hpp"
#include "gaits/export/metrics.hpp"
#include "gaits/trajectory/physical_joints.hpp"

namespace gaitopt::gaits {
namespace {

constexpr const char* kTailColumns[] = {"fb_x",  "fb_y",    "fe_x",    "fe_y",  "zmp_x", "hip_x",
                                        "hip_y", "swing_x", "swing_y", "com_x", "com_y"};

}  // namespace

/// The columns of Mu's coordinates and the derived positions, for an n-link robot.
std::vector<std::string> muColumnNames(int n) {
  std::vector<std::string> names{"t", "phase"};
  const auto add = [&](const char* prefix, int first) {
    for (int i = 0; i < n; ++i) names.push_back(fmt::format("{}{}", prefix, first + i));
  };
  add("theta", 1);
  add("dtheta", 1);
  add("ddtheta", 1);
  add("q", 0);
  add("dq", 0);
  add("tau", 0);
  names.insert(names.end(), std::begin(kTailColumns), std::end(kTailColumns));
  return names;
}

/// Column names of docs/design.md#the-export-contract for an n-link robot: angles 1-based like Mu's
/// links, joint quantities 0-based like q0 = stance ankle; then the physical joints
/// (physical_joints.hpp): angles, rates ("d" + name) and torques ("tau_" + name).
std::vector<std::string> columnNames(const dynamics::Model& model) {
  std::vector<std::string> names = muColumnNames(model.nLinks());
  const auto joints = physicalJoints(model);
  for (const char* prefix : {"", "d", "tau_"})
    for (const auto& j : joints) names.push_back(prefix + j.name);
  return names;
}

Eigen::VectorXd rowNumbers(const Knot& knot, const dynamics::Model& model,
                           const std::vector<PhysicalJoint>& joints, double step_length) {
  const VecD theta = knot.theta, dtheta = knot.dtheta;
  const double zmp = zmpX(knot, step_length);
  if (!std::isfinite(zmp))
    throw std::invalid_argument(fmt::format(
        "knot at t = {}: the total vertical ground force is zero, so the ZMP is undefined; a "
        "reference trajectory needs its contact forces",
        knot.t));
  const VecD q = dynamics::toJoint(theta), dq = dynamics::toJoint(dtheta);
  const int n = model.nLinks(), p = static_cast<int>(joints.size());
  Eigen::VectorXd row(6 * n + 11 + 3 * p);
  row << knot.theta, knot.dtheta, knot.ddtheta, Eigen::VectorXd(q), Eigen::VectorXd(dq), knot.tau,
      knot.force_stance, knot.force_swing, zmp, dynamics::hip(model, theta),
      dynamics::swingTip(model, theta), dynamics::centreOfMass(model, theta),
      physicalValues(joints, q, true), physicalValues(joints, dq, false),
      physicalValues(joints, VecD(knot.tau), false);
  return row;
}

}  // namespace gaitopt::gaits
