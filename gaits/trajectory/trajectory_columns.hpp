#pragma once
/// @file trajectory_columns.hpp
/// The columns of an exported trajectory (docs/design.md#the-export-contract), one definition for
/// trajectory.csv and trajectory.json: t, phase, Mu's absolute angles theta, rates and
/// accelerations, joint angles q and rates dq (Mu 2.41), torques tau, the tip forces, the ZMP, hip,
/// swing tip and centre of mass, then the physical joints' angles, rates ("d" + name) and torques
/// ("tau_" + name) (physical_joints.hpp).
#include <string>
#include <vector>

#include "dynamics/model.hpp"
#include "gaits/trajectory/physical_joints.hpp"
#include "gaits/trajectory/trajectory.hpp"

namespace gaitopt::gaits {

/// The columns of Mu's coordinates and the derived positions, for an n-link robot.
std::vector<std::string> muColumnNames(int n);

/// Every column of `model`'s export, "t" and "phase" first.
std::vector<std::string> columnNames(const dynamics::Model& model);

/// The numbers of one row, after t and phase, in columnNames order; `joints` are
/// physicalJoints(model), found once per file.
/// @throws std::invalid_argument when the knot has no vertical ground force (no ZMP).
Eigen::VectorXd rowNumbers(const Knot& knot, const dynamics::Model& model,
                           const std::vector<PhysicalJoint>& joints, double step_length);

}  // namespace gaitopt::gaits
