#include "library/library_folder.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>

#include <fmt/format.h>

#include "config/config_error.hpp"
#include "gaits/export/gait_folder_checks.hpp"
#include "gaits/export/gait_summary.hpp"
#include "gaits/trajectory/trajectory_csv.hpp"
#include "io/data_dir.hpp"
#include "io/settings_record.hpp"
#include "io/strict_json.hpp"

namespace gaitopt::library {
namespace {

/// The base OCP file relative to the library folder, so the folder and the configs can move
/// together (a clone of the repository elsewhere).
std::string ocpPathFromFolder(const LibrarySetup& s) {
  namespace fs = std::filesystem;
  return fs::relative(fs::absolute(s.config.ocp_path), fs::absolute(s.out_dir)).string();
}

/// The last run that solved something: a rerun with nothing left to do keeps the figures of
/// the run that built the library.
nlohmann::ordered_json lastRun(const std::string& path, const RunStats& s) {
  if (s.points == 0 && std::filesystem::exists(path)) {
    std::ifstream in(path);
    const auto previous = nlohmann::ordered_json::parse(in, nullptr, false);
    if (!previous.is_discarded() && previous.contains("last_run")) return previous["last_run"];
  }
  return {{"points", s.points},
          {"failed", s.failed},
          {"solves", s.solves},
          {"workers", s.workers},
          {"wall_time_s", s.wall_time_s},
          {"points_per_second", s.wall_time_s > 0 ? s.points / s.wall_time_s : 0.0}};
}

/// @throws config::ConfigError naming `file`, `why` it is no point's gait, and the remedy.
[[noreturn]] void refuseDamaged(const std::string& file, const std::string& why) {
  throw config::ConfigError(file, "", 0,
                            why +
                                ": the library folder was edited or damaged; rerun gaitopt "
                                "library on it to solve the point again");
}

/// A point's gait is what the grid says it is: a gait of this robot (gaits::requireGaitOf) of
/// the point's slope, step length and step time. A folder copied over another point's or another
/// robot's point otherwise blended in unseen.
void checkPointGait(const std::string& point_dir, const gaits::Trajectory& traj,
                    const GridPoint& point, const dynamics::Model& model) {
  const std::string summary = point_dir + "/summary.json";
  gaits::requireGaitOf(point_dir, model);
  const double slope_rad = io::readStrictJson(summary).value("slope_rad", 0.0);
  const auto [speed, length, slope] = point.walk();
  const double step_time = length / speed;
  if (std::abs(traj.stepLength() - length) > 1e-9 * length ||
      std::abs(traj.duration() - step_time) > 1e-6 * step_time ||
      std::abs(slope_rad - slope) > 1e-9)
    refuseDamaged(
        point_dir + "/trajectory.csv",
        fmt::format("a step of {:g} m in {:g} s on slope {:g}, not the point's {:g} m in {:g} "
                    "s on {:g}",
                    traj.stepLength(), traj.duration(), slope_rad, length, step_time, slope));
}

/// The files the points were solved from, as they are now against the fingerprints the library
/// recorded (libraryClaim): a gait blended for a robot edited since is another robot's motion
/// with this one's torques. A library made before a key was recorded is not judged on it.
void refuseChangedInputs(const std::string& library_file, const nlohmann::ordered_json& claim,
                         const std::string& ocp_path, const ocp::OcpConfig& base) {
  const std::vector<std::pair<const char*, std::string>> inputs = {
      {"ocp_config_fnv1a", ocp_path},
      {"robot_file_fnv1a", base.robot_path},
      {"guess_gait_fnv1a", base.guess_gait_path}};
  for (const auto& [key, file] : inputs)
    if (claim.contains(key) && !file.empty() && claim[key] != io::fileFingerprint(file))
      throw config::ConfigError(library_file, key, 0,
                                fmt::format("{} has changed since the library was solved: its "
                                            "gaits are of the file as it was; rerun gaitopt "
                                            "library into a new folder",
                                            file));
}

/// The base OCP file: relative to the library folder as recorded (the folder and the configs
/// moved together), else the shipped file of that name when its contents are the ones the
/// library recorded (a copy of a shipped library, e.g. results/library_mu2004, elsewhere).
std::string ocpOfFolder(const std::string& dir, const nlohmann::ordered_json& claim) {
  const std::filesystem::path recorded =
      std::filesystem::path(dir) / claim["ocp"].get<std::string>();
  if (std::filesystem::exists(recorded) || !claim.contains("ocp_config_fnv1a"))
    return recorded.string();
  const std::string shipped = io::localOrShipped("configs/ocp/" + recorded.filename().string());
  return !shipped.empty() && io::fileFingerprint(shipped) == claim["ocp_config_fnv1a"]
             ? shipped
             : recorded.string();
}

}  // namespace

GaitLookup FolderGaits::lookup() {
  return [this](int p) -> const gaits::Trajectory* {
    auto& slot = cache_[p];
    if (slot) return slot.get();
    const std::string point = dir_ + "/points/" + grid_->point(p).name;
    const std::string csv = point + "/trajectory.csv";
    if (std::filesystem::exists(csv)) {
      // Before the CSV: its rows need the phase switches the summary holds.
      if (!std::filesystem::is_regular_file(point + "/summary.json"))
        refuseDamaged(point + "/summary.json", "missing beside its trajectory.csv");
      auto gait = std::make_unique<gaits::Trajectory>(gaits::readTrajectoryCsv(csv, *model_));
      checkPointGait(point, *gait, grid_->point(p), *model_);
      slot = std::move(gait);
      return slot.get();
    }
    // A solved point's folder without its gait is a damaged library, not an unsolved point.
    if (std::filesystem::exists(point + "/summary.json"))
      refuseDamaged(csv, "missing beside its summary.json");
    return nullptr;  // not solved
  };
}

LibraryFolder readLibraryFolder(const std::string& dir) {
  const std::string path = dir + "/" + kLibraryFile;
  if (!std::filesystem::is_regular_file(path))
    throw config::ConfigError(path, "", 0, "not a gait library folder (no library.json)");
  const auto j = io::readStrictJson(path);
  if (!j.is_object() || !j.contains("axes") || !j.contains("ocp"))
    throw config::ConfigError(path, "", 0, "not a library.json written by gaitopt library");
  const auto& axes = j.at("axes");
  // Each axis a non-empty increasing list of numbers, as libraryClaim writes it; an edited
  // file is refused by name rather than read as another grid.
  const auto axis = [&](const std::string& key) {
    std::vector<double> values;
    if (axes.is_object() && axes.contains(key) && axes[key].is_array())
      for (const auto& v : axes[key])
        if (v.is_number()) values.push_back(v.get<double>());
    if (values.empty() || values.size() != axes[key].size() ||
        std::adjacent_find(values.begin(), values.end(), std::greater_equal<>()) != values.end())
      throw config::ConfigError(path, "axes." + key, 0,
                                "expected an increasing list of numbers: the library folder was "
                                "edited or damaged");
    return values;
  };
  std::array<std::vector<double>, kWalkAxes> walk;
  for (int a = 0; a < kWalkAxes; ++a) walk[a] = axis(kAxisNames[a]);
  std::vector<GridAxis> config;
  const auto keys = j.value("config_axes", nlohmann::ordered_json::array());
  for (const auto& key : keys) {
    if (!key.is_string())
      throw config::ConfigError(path, "config_axes", 0, "expected a list of config keys");
    config.push_back({key.get<std::string>(), axis(key.get<std::string>())});
  }
  // The OCP path is relative to the library folder (claimLibraryFolder).
  if (!j.at("ocp").is_string())
    throw config::ConfigError(path, "ocp", 0, "expected the base OCP file's path");
  const std::string ocp_path = ocpOfFolder(dir, j);
  LibraryFolder folder{Grid(walk, std::move(config)), ocp::loadOcpConfig(ocp_path)};
  refuseChangedInputs(path, j, ocp_path, folder.base);
  return folder;
}

nlohmann::ordered_json libraryClaim(const LibrarySetup& s) {
  nlohmann::ordered_json axes;
  for (int a = 0; a < s.grid.dimensions(); ++a) axes[s.grid.axisName(a)] = s.grid.axes()[a];
  nlohmann::ordered_json claim = {
      {"name", s.config.name}, {"ocp", ocpPathFromFolder(s)}, {"axes", axes}};
  // The config keys swept, in the grid's order (a JSON object's keys have none). Keyed only
  // when there are some, so a folder of a speed/step/slope library still resumes.
  if (!s.grid.configAxes().empty()) {
    auto& keys = claim["config_axes"] = nlohmann::ordered_json::array();
    for (const auto& axis : s.grid.configAxes()) keys.push_back(axis.key);
  }
  // The contents of every file the points are solved from (not their paths, which differ
  // between machines), and the rate every point's trajectory.csv is written at.
  claim["library_config_fnv1a"] = io::fileFingerprint(s.config.path);
  claim["ocp_config_fnv1a"] = io::fileFingerprint(s.config.ocp_path);
  claim["robot_file_fnv1a"] = io::fileFingerprint(s.config.base.robot_path);
  if (!s.config.base.guess_gait_path.empty())
    claim["guess_gait_fnv1a"] = io::fileFingerprint(s.config.base.guess_gait_path);
  claim["rate_hz"] = s.result.rate_hz;
  // Values set on the command line change the library config without changing its file. Keyed
  // only when given, so a folder made without them still resumes.
  if (!s.result.config_overrides.empty()) claim["config_overrides"] = s.result.config_overrides;
  return claim;
}

void claimLibraryFolder(const LibrarySetup& s) {
  io::claimSettings(s.out_dir + "/" + kLibraryFile, libraryClaim(s));
}

ScheduleState previousState(const LibrarySetup& s, const LibraryIndex& index, bool retry_failed) {
  const auto n = static_cast<std::size_t>(s.grid.size());
  ScheduleState state{std::vector<bool>(n, false), std::vector<bool>(n, false)};
  for (int p = 0; p < s.grid.size(); ++p) {
    const auto row = index.row(s.grid.point(p).name);
    if (!row) continue;
    const bool solved =
        row->converged && std::filesystem::exists(s.pointDir(p) + "/trajectory.csv");
    state.solved[static_cast<std::size_t>(p)] = solved;
    state.finished[static_cast<std::size_t>(p)] = solved || (!row->converged && !retry_failed);
  }
  return state;
}

void writeIndexJson(const LibrarySetup& setup, const LibraryIndex& index, const RunStats& s) {
  const std::string path = setup.out_dir + "/index.json";
  auto json = index.json(setup.grid);
  json["last_run"] = lastRun(path, s);
  gaits::writeJsonFile(json, path);
}

}  // namespace gaitopt::library
