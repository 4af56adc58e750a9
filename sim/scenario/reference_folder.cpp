#include "sim/scenario/reference_folder.hpp"

#include <cmath>
#include <filesystem>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "config/config_error.hpp"
#include "dynamics/model_variation.hpp"
#include "dynamics/robot_files/robot_config.hpp"
#include "gaits/trajectory/trajectory_csv.hpp"
#include "io/data_dir.hpp"
#include "io/strict_json.hpp"
#include "io/terminal_text.hpp"

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

namespace {

/// requireGaitOf's checks; the folder's summary.json when it has one (null when not).
nlohmann::ordered_json checkedSummary(const std::string& dir, const dynamics::Model& model) {
  if (std::filesystem::exists(dir + "/FAILED.txt"))
    throw config::ConfigError(dir, "", 0,
                              "holds a failed solve (FAILED.txt), not a gait: use a converged "
                              "result");
  const std::string summary = dir + "/summary.json";
  if (!std::filesystem::is_regular_file(summary)) return nullptr;  // a bare trajectory.csv
  const auto json = io::readStrictJson(summary);
  if (!json.is_object()) throw config::ConfigError(summary, "", 0, "expected a JSON object");
  if (json.contains("converged") && json["converged"] == false)
    throw config::ConfigError(summary, "converged", 0,
                              "the solve did not converge: this is not a gait to use");
  if (json.contains("robot") && json["robot"].is_string() && json["robot"] != model.name())
    throw config::ConfigError(
        summary, "robot", 0,
        fmt::format("the gait is of robot '{}', not of robot '{}' used here",
                    io::printable(json["robot"].get<std::string>()), model.name()));
  return json;
}

}  // namespace

void requireGaitOf(const std::string& dir, const dynamics::Model& model) {
  checkedSummary(dir, model);
}

void requireDesignedFor(const std::string& dir, const dynamics::Model& model) {
  const nlohmann::ordered_json json = checkedSummary(dir, model);
  // A robot file of the same name with other masses (a copy edited and solved on) is another
  // robot: its gait walked the shipped one, which it does not fit, without a word.
  if (json.contains("total_mass") && json["total_mass"].is_number() &&
      std::abs(json["total_mass"].get<double>() - model.totalMass()) > 1e-9 * model.totalMass())
    throw config::ConfigError(
        dir + "/summary.json", "total_mass", 0,
        fmt::format("the gait was designed for a robot '{}' of {:g} kg; the robot file used here "
                    "weighs {:g} kg: give the file it was designed on (--robot), or walk a mass "
                    "error (--mass-error)",
                    model.name(), json["total_mass"].get<double>(), model.totalMass()));
}

ReferenceFolder loadReferenceFolder(const std::string& dir, const std::string& robot_path,
                                    const std::vector<config::Override>& robot_overrides) {
  if (!std::filesystem::is_directory(dir))
    throw config::ConfigError(dir, "", 0, "not a folder (expected a gait result folder)");
  const std::string robot = robot_path.empty() ? robotOfFolder(dir) : robot_path;
  // The plant and the controller's model walk on the slope the reference was designed for.
  const double slope = slopeOfFolder(dir);
  // The gait is checked against the robot file as it is; --set robot.KEY=V then changes the
  // robot it walks on, on purpose.
  requireDesignedFor(dir, dynamics::withSlope(dynamics::loadRobot(robot), slope));
  dynamics::Model model = dynamics::withSlope(dynamics::loadRobot(robot, robot_overrides), slope);
  gaits::Trajectory step = gaits::readTrajectoryCsv(dir + "/trajectory.csv", model);
  if (step.knots().size() < 2)
    throw config::ConfigError(
        dir + "/trajectory.csv", "", 0,
        fmt::format("{} sample(s): a step needs at least 2", step.knots().size()));
  return {dir, robot, std::move(model), std::move(step)};
}

}  // namespace gaitopt::sim
