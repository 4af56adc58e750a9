#pragma once
/// @file reference_folder.hpp
/// A gait result folder (from `gaitopt poly` or `gaitopt optimize`) as the input of the
/// closed-loop commands: its robot and its one-step trajectory.csv.
#include <string>
#include <vector>

#include "config/overrides.hpp"

#include "dynamics/model.hpp"
#include "gaits/trajectory/trajectory.hpp"

namespace gaitopt::sim {

struct ReferenceFolder {
  std::string dir;
  std::string robot_path;
  dynamics::Model model;
  gaits::Trajectory step;
};

/// The robot file named by the result folder's summary.json ("robot"), by the configs/robots
/// convention: configs/robots/NAME.yaml under the working directory (a user's own robots), else
/// the shipped one (io/data_dir.hpp).
/// @throws config::ConfigError when the folder has no summary, it names no robot, or neither
///         file exists.
std::string robotOfFolder(const std::string& dir);

/// Reads DIR/trajectory.csv (with the switch states of DIR/summary.json put back, so the step's
/// SSP ends at the touchdown in the pre-impact state and its DSP ends at the period:
/// gaits/trajectory/trajectory_csv.hpp) for the robot `robot_path`, or, when that is empty, for
/// configs/robots/<summary.json's "robot">.yaml under the working directory. The model carries
/// summary.json's "slope_rad" (0 when absent), so a simulation walks the reference's slope.
/// @throws config::ConfigError naming the file and what is wrong (missing folder, unknown robot,
///         a trajectory that does not fit the robot).
/// `robot_overrides` replace values of the robot file (a command's --set robot.KEY=V).
ReferenceFolder loadReferenceFolder(const std::string& dir, const std::string& robot_path,
                                    const std::vector<config::Override>& robot_overrides = {});

}  // namespace gaitopt::sim
