#include "report/report_folder.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>

#include <fmt/format.h>

#include "config/config_error.hpp"
#include "dynamics/robot_files/robot_config.hpp"
#include "report/report_frames.hpp"
#include "sim/scenario/reference_folder.hpp"

namespace gaitopt::report {
namespace {

namespace fs = std::filesystem;

constexpr double kGaitFrameRate = 100;  // [Hz] smooth at screen rates, small page

bool has(const std::string& dir, const std::string& file) {
  return fs::is_regular_file(fs::path(dir) / file);
}

nlohmann::ordered_json readJson(const std::string& path) {
  std::ifstream in(path);
  auto json = nlohmann::ordered_json::parse(in, nullptr, false);
  if (!in || json.is_discarded()) throw config::ConfigError(path, "", 0, "not readable JSON");
  return json;
}

/// The files of `dir` whose names start with `prefix` and end with `suffix`, sorted.
std::vector<std::string> filesOf(const std::string& dir, const std::string& prefix,
                                 const std::string& suffix) {
  std::vector<std::string> files;
  for (const auto& entry : fs::directory_iterator(dir)) {
    const std::string name = entry.path().filename().string();
    if (entry.is_regular_file() && name.starts_with(prefix) && name.ends_with(suffix))
      files.push_back(entry.path().string());
  }
  std::sort(files.begin(), files.end());
  return files;
}

std::vector<std::string> linkNames(const dynamics::Model& model) {
  std::vector<std::string> names;
  for (const auto& link : model.links()) names.push_back(link.name);
  return names;
}

/// One step of a gait folder, B at the origin.
void animateGait(ReportContent& c, const sim::ReferenceFolder& gait) {
  c.frames = framesJson(gaitFrames(gait.model, gait.step, kGaitFrameRate));
  c.link_names = linkNames(gait.model);
  c.foot_heel = gait.model.foot().heel;
  c.foot_toe = gait.model.foot().toe;
  c.animation_note = fmt::format(
      "One step of {}/trajectory.csv ({}), drawn in the frame of the stance tip; it loops. "
      "Each step the legs swap (relabelling, Mu sec. 2.4).",
      gait.dir, gait.model.name());
}

/// The robot a walk folder's summary names: its robot_file as simulate found it (a path from
/// where simulate ran), else the robot file of that name (sim::robotOfFolder); empty if neither.
std::string walkRobotFile(const ReportContent& c, const std::string& dir) {
  const std::string recorded = c.summary.value("robot_file", "");
  if (!recorded.empty() && fs::is_regular_file(recorded)) return recorded;
  try {
    return sim::robotOfFolder(dir);
  } catch (const config::ConfigError&) {
    return "";  // the page is still drawn, its links unnamed
  }
}

/// The plant's own foot from a walk's summary, which the robot file found by name need not have
/// (walks written since 2026-12-01 record it); the foot of c unchanged without the key.
void takeSummaryFoot(ReportContent& c) {
  const auto& foot = c.summary.value("foot", nlohmann::ordered_json::object());
  if (!foot.contains("heel") || !foot["heel"].is_number() || !foot.contains("toe") ||
      !foot["toe"].is_number())
    return;
  c.foot_heel = foot["heel"].get<double>();
  c.foot_toe = foot["toe"].get<double>();
}

/// The walk as simulated, every step in the world frame (stick.csv).
void animateWalk(ReportContent& c, const std::string& dir) {
  c.frames = framesJson(readStickCsv(dir + "/stick.csv"));
  if (const std::string robot = walkRobotFile(c, dir); !robot.empty()) {
    const dynamics::Model model = dynamics::loadRobot(robot);
    c.link_names = linkNames(model);
    c.foot_heel = model.foot().heel;
    c.foot_toe = model.foot().toe;
  }
  takeSummaryFoot(c);
  c.animation_note = fmt::format(
      "The closed-loop walk of {}/stick.csv in the world frame; link colours follow the legs "
      "as labelled at each step's start (stance leg first).",
      dir);
}

/// A library shows its first solved point that kept its trajectory.
void animateLibraryPoint(ReportContent& c, const std::string& dir, const std::string& robot_path) {
  const std::string points = dir + "/points";
  std::vector<std::string> folders;
  if (fs::is_directory(points))
    for (const auto& entry : fs::directory_iterator(points))
      if (has(entry.path().string(), "trajectory.csv")) folders.push_back(entry.path().string());
  std::sort(folders.begin(), folders.end());
  if (folders.empty()) {
    c.animation_note = "No point of the library kept its trajectory.csv (points/ is empty).";
    return;
  }
  animateGait(c, sim::loadReferenceFolder(folders.front(), robot_path));
}

/// @throws config::ConfigError unless `gait` is of the robot the sweep of `dir` walked. The
/// reference folder may have been remade for another robot since the sweep; its step would then
/// be drawn, as the sweep's, with that robot's lengths (simulate refuses such a pair the same way).
void requireSweptRobot(const std::string& dir, const nlohmann::ordered_json& summary,
                       const sim::ReferenceFolder& gait) {
  const auto robot = summary.find("robot");
  if (robot == summary.end() || !robot->is_string() || *robot == gait.model.name()) return;
  throw config::ConfigError(
      dir + "/summary.json", "robot", 0,
      fmt::format("the sweep walked robot '{}', but its reference {} is a gait of robot '{}'",
                  robot->get<std::string>(), gait.dir, gait.model.name()));
}

/// A stability sweep shows the reference gait it walked, when that folder is still there.
void animateReference(ReportContent& c, const std::string& dir, const std::string& robot_path) {
  const std::string ref = c.summary.value("reference", "");
  if (ref.empty() || !has(ref, "trajectory.csv")) {
    c.animation_note = fmt::format("The reference gait '{}' is not here to animate.", ref);
    return;
  }
  const sim::ReferenceFolder gait = sim::loadReferenceFolder(ref, robot_path);
  requireSweptRobot(dir, c.summary, gait);
  animateGait(c, gait);
}

}  // namespace

ReportContent collectReport(const std::string& dir, const std::string& robot_path) {
  if (!fs::is_directory(dir))
    throw config::ConfigError(dir, "", 0, "no such folder: expected a gaitopt result folder");
  ReportContent c;
  c.title = fs::path(dir).lexically_normal().filename().string();
  if (c.title.empty()) c.title = fs::path(dir).lexically_normal().parent_path().filename().string();
  c.charts = filesOf(dir, "", ".png");
  if (has(dir, "library.json")) {
    c.kind = "library";
    c.summary = readJson(dir + "/library.json");
    c.tables = filesOf(dir, "index", ".csv");
    animateLibraryPoint(c, dir, robot_path);
    return c;
  }
  if (has(dir, "comparison.md"))
    throw config::ConfigError(dir, "", 0,
                              "a comparison (gaitopt compare) has no page of its own: open its "
                              "comparison.md, or report each gait it compares");
  if (!has(dir, "summary.json"))
    throw config::ConfigError(dir, "", 0,
                              "not a gaitopt result folder: no summary.json or library.json");
  c.summary = readJson(dir + "/summary.json");
  if (has(dir, "stick.csv")) {
    c.kind = "walk";
    c.tables = filesOf(dir, "steps", ".csv");
    animateWalk(c, dir);
  } else if (has(dir, "trajectory.csv")) {
    c.kind = "gait";
    animateGait(c, sim::loadReferenceFolder(dir, robot_path));
  } else if (c.summary.contains("sweeps") || c.summary.contains("maps")) {
    c.kind = "stability";
    c.tables = filesOf(dir, "sweep_", ".csv");
    for (auto& t : filesOf(dir, "map_", ".csv")) c.tables.push_back(std::move(t));
    animateReference(c, dir, robot_path);
  } else {
    throw config::ConfigError(dir, "", 0,
                              "not a gait, walk, library or stability folder: no trajectory.csv, "
                              "stick.csv, library.json, or sweeps or maps in summary.json");
  }
  return c;
}

}  // namespace gaitopt::report
