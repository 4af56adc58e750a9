#include "apps/reference_folder.hpp"

#include <filesystem>
#include <fstream>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "config/config_error.hpp"
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

}  // namespace

ReferenceFolder loadReferenceFolder(const std::string& dir, const std::string& robot_path) {
  if (!std::filesystem::is_directory(dir))
    throw config::ConfigError(dir, "", 0, "not a folder (expected a gait result folder)");
  const std::string robot = robot_path.empty() ? robotOfFolder(dir) : robot_path;
  dynamics::Model model = dynamics::loadRobot(robot);
  gaits::Trajectory step = gaits::readTrajectoryCsv(dir + "/trajectory.csv", model);
  return {dir, robot, std::move(model), std::move(step)};
}

}  // namespace gaitopt::apps
