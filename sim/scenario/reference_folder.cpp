#include "sim/scenario/reference_folder.hpp"

#include <cmath>
#include <filesystem>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "config/config_error.hpp"
#include "dynamics/model_variation.hpp"
#include "dynamics/robot_files/robot_config.hpp"
#include "gaits/export/gait_folder_checks.hpp"
#include "gaits/trajectory/trajectory_csv.hpp"
#include "io/data_dir.hpp"
#include "io/strict_json.hpp"

namespace gaitopt::sim {

std::string robotOfFolder(const std::string& dir) {
  const std::string summary = dir + "/summary.json";
  if (!std::filesystem::is_regular_file(summary))
    throw config::ConfigError(summary, "", 0,
                              "missing: a gait result folder holds trajectory.csv and "
                              "summary.json (gaitopt poly and optimize write both)");
  const auto json = io::readStrictJson(summary);
  if (!json.is_object() || !json.contains("robot") || !json["robot"].is_string())
    throw config::ConfigError(summary, "robot", 0, "expected the robot's name (or pass --robot)");
  const std::string path = "configs/robots/" + json["robot"].get<std::string>() + ".yaml";
  if (std::string found = io::localOrShipped(path); !found.empty()) return found;
  throw config::ConfigError(
      summary, "robot", 0,
      fmt::format("no {} under the working directory nor among the shipped robots ({}); pass "
                  "--robot FILE",
                  path, io::dataDir()));
}

namespace {

/// The ground slope the gait was designed for: summary.json's "slope_rad", 0 when the folder
/// has no summary or the key (results written before slopes existed) [rad].
double slopeOfFolder(const std::string& dir) {
  const std::string summary = dir + "/summary.json";
  if (!std::filesystem::is_regular_file(summary)) return 0.0;
  const auto json = io::readStrictJson(summary);
  if (!json.is_object() || !json.contains("slope_rad")) return 0.0;
  const auto& slope = json["slope_rad"];
  if (!slope.is_number() || !(std::abs(slope.get<double>()) <= dynamics::kMaxConfigSlope))
    throw config::ConfigError(summary, "slope_rad", 0,
                              fmt::format("expected a slope in [-{0}, {0}] rad, got {1}",
                                          dynamics::kMaxConfigSlope, slope.dump()));
  return slope.get<double>();
}

}  // namespace

ReferenceFolder loadReferenceFolder(const std::string& dir, const std::string& robot_path,
                                    const std::vector<config::Override>& robot_overrides) {
  if (!std::filesystem::is_directory(dir))
    throw config::ConfigError(dir, "", 0, "not a folder (expected a gait result folder)");
  const std::string robot = robot_path.empty() ? robotOfFolder(dir) : robot_path;
  // The plant and the controller's model walk on the slope the reference was designed for.
  const double slope = slopeOfFolder(dir);
  // The gait is checked against the robot file as it is; --set robot.KEY=V then changes the
  // robot it walks on, on purpose.
  gaits::requireDesignedFor(dir, dynamics::withSlope(dynamics::loadRobot(robot), slope));
  dynamics::Model model = dynamics::withSlope(dynamics::loadRobot(robot, robot_overrides), slope);
  gaits::Trajectory step = gaits::readTrajectoryCsv(dir + "/trajectory.csv", model);
  if (step.knots().size() < 2)
    throw config::ConfigError(
        dir + "/trajectory.csv", "", 0,
        fmt::format("{} sample(s): a step needs at least 2", step.knots().size()));
  return {dir, robot, std::move(model), std::move(step)};
}

}  // namespace gaitopt::sim
