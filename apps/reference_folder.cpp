#include "apps/reference_folder.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "config/config_error.hpp"
#include "dynamics/model_variation.hpp"
#include "dynamics/robot_config.hpp"
#include "gaits/trajectory_csv.hpp"

namespace gaitopt::apps {
namespace {

/// The robot file named by the folder's summary.json, by the configs/robots convention.
std::string robotOfFolder(const std::string& dir) {
  const std::string summary = dir + "/summary.json";
  std::ifstream in(summary);
  if (!in)
    throw config::ConfigError(summary, "", 0,
                              "cannot read it: is this a gait result folder? (or pass --robot)");
  const auto json = nlohmann::json::parse(in, nullptr, false);
  if (json.is_discarded() || !json.contains("robot") || !json["robot"].is_string())
    throw config::ConfigError(summary, "robot", 0, "expected the robot's name (or pass --robot)");
  const std::string path = "configs/robots/" + json["robot"].get<std::string>() + ".yaml";
  if (!std::filesystem::exists(path))
    throw config::ConfigError(
        summary, "robot", 0,
        fmt::format("no {} under the working directory; pass --robot FILE", path));
  return path;
}

/// The ground slope the gait was designed for: summary.json's "slope_rad", 0 when the folder
/// has no summary or the key (results written before slopes existed) [rad].
double slopeOfFolder(const std::string& dir) {
  const std::string summary = dir + "/summary.json";
  std::ifstream in(summary);
  if (!in) return 0.0;
  const auto json = nlohmann::json::parse(in, nullptr, false);
  if (json.is_discarded() || !json.contains("slope_rad")) return 0.0;
  const auto& slope = json["slope_rad"];
  if (!slope.is_number() || !(std::abs(slope.get<double>()) <= dynamics::kMaxConfigSlope))
    throw config::ConfigError(summary, "slope_rad", 0,
                              fmt::format("expected a slope in [-{0}, {0}] rad, got {1}",
                                          dynamics::kMaxConfigSlope, slope.dump()));
  return slope.get<double>();
}

}  // namespace

ReferenceFolder loadReferenceFolder(const std::string& dir, const std::string& robot_path) {
  if (!std::filesystem::is_directory(dir))
    throw config::ConfigError(dir, "", 0, "not a folder (expected a gait result folder)");
  const std::string robot = robot_path.empty() ? robotOfFolder(dir) : robot_path;
  // The plant and the controller's model walk on the slope the reference was designed for.
  dynamics::Model model = dynamics::withSlope(dynamics::loadRobot(robot), slopeOfFolder(dir));
  gaits::Trajectory step = gaits::readTrajectoryCsv(dir + "/trajectory.csv", model);
  return {dir, robot, std::move(model), std::move(step)};
}

}  // namespace gaitopt::apps
