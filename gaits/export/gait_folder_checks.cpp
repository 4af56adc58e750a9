#include "gaits/export/gait_folder_checks.hpp"

#include <cmath>
#include <filesystem>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "config/config_error.hpp"
#include "io/strict_json.hpp"
#include "io/terminal_text.hpp"

namespace gaitopt::gaits {

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

}  // namespace gaitopt::gaits
