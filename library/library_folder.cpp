#include "library/library_folder.hpp"

#include <filesystem>
#include <fstream>

#include "config/config_error.hpp"
#include "gaits/export/gait_summary.hpp"
#include "gaits/trajectory/trajectory_csv.hpp"
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

}  // namespace

GaitLookup FolderGaits::lookup() {
  return [this](int p) -> const gaits::Trajectory* {
    auto& slot = cache_[p];
    if (slot) return slot.get();
    const std::string point = dir_ + "/points/" + grid_->point(p).name;
    const std::string csv = point + "/trajectory.csv";
    if (std::filesystem::exists(csv)) {
      slot = std::make_unique<gaits::Trajectory>(gaits::readTrajectoryCsv(csv, *model_));
      return slot.get();
    }
    // A solved point's folder without its gait is a damaged library, not an unsolved point.
    if (std::filesystem::exists(point + "/summary.json"))
      throw config::ConfigError(csv, "", 0,
                                "missing beside its summary.json: the library folder was edited "
                                "or damaged; rerun gaitopt library on it to solve the point again");
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
  std::array<std::vector<double>, kWalkAxes> walk;
  for (int a = 0; a < kWalkAxes; ++a) walk[a] = axes.at(kAxisNames[a]).get<std::vector<double>>();
  std::vector<GridAxis> config;
  for (const auto& key : j.value("config_axes", std::vector<std::string>{}))
    config.push_back({key, axes.at(key).get<std::vector<double>>()});
  // The OCP path is relative to the library folder (claimLibraryFolder).
  const auto ocp_path = std::filesystem::path(dir) / j.at("ocp").get<std::string>();
  return {Grid(walk, std::move(config)), ocp::loadOcpConfig(ocp_path.string())};
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
