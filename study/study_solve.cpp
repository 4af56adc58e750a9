#include "study/study_solve.hpp"

#include <filesystem>
#include <fstream>

#include <fmt/format.h>

#include "io/output/checked_write.hpp"

namespace gaitopt::study {
namespace fs = std::filesystem;
namespace {

using Pointer = nlohmann::json::json_pointer;

/// `gaitopt poly` of a polynomial gait, else `gaitopt optimize` with the point's --set values.
std::vector<std::string> solveArgs(const StudyPoint& p) {
  if (!p.robot.empty()) return {"poly", "--robot", p.robot, "--gait", p.config};
  std::vector<std::string> args = {"optimize", "--config", p.config, "--quiet"};
  for (const config::Override& o : p.overrides) args.insert(args.end(), {"--set", o.text()});
  return args;
}

/// The cost of the converged optimum (or the polynomial gait) in `dir`, or nothing.
std::optional<double> costOf(const std::string& dir) {
  const auto s = readSummary(dir);
  if (!s || !s->value("converged", true)) return std::nullopt;
  return s->at("cost").get<double>();
}

/// Whether the run into `out` ended for good: a result (a solve's or a failed solve's) or a
/// recorded refusal. One killed or stopped by the machine did not, and is redone (runTool).
bool ended(const std::string& out) {
  return fs::exists(out + "/summary.json") || fs::exists(out + ".failed/summary.json") ||
         fs::exists(out + ".exit");
}

/// Moves `from` (and its log) to `to`, replacing what was there, its .failed twin and the exit
/// status its failure recorded.
void replaceWith(const std::string& from, const std::string& to) {
  fs::remove_all(to);
  fs::remove_all(to + ".failed");
  fs::remove(to + ".exit");
  fs::rename(from, to);
  fs::rename(from + ".log", to + ".log");
}

/// Solves point p from the previous point's optimum into `out`.
void solveFrom(const StudyPoint& p, const StudyPoint& previous, const std::string& dir,
               const std::string& out, const StudyTools& t) {
  std::vector<std::string> args = solveArgs(p);
  args.insert(args.end(), {"--warm-start", gaitFolder(previous, dir)});
  runTool(t, args, out, fmt::format("solve {} from {}", p.folder, previous.folder));
}

/// Solves from the previous point's optimum into FOLDER.warm and keeps it when it is cheaper.
void warmSolve(const StudyPoint& p, const StudyPoint& previous, const std::string& dir,
               const StudyTools& t) {
  const std::string cold = gaitFolder(p, dir), warm = cold + ".warm";
  fs::remove_all(warm);
  solveFrom(p, previous, dir, warm, t);
  if (!ended(warm)) return;  // no .start: the next run of the study tries it again
  const auto cold_cost = costOf(cold), warm_cost = costOf(warm);
  const bool keep_warm = warm_cost && (!cold_cost || *warm_cost < *cold_cost);
  if (keep_warm) replaceWith(warm, cold);
  fs::remove_all(warm);
  fs::remove_all(warm + ".failed");
  fs::remove(warm + ".log");
  fs::remove(warm + ".exit");
  io::writeFileAtomically(cold + ".start", keep_warm ? previous.folder : "guess");
}

}  // namespace

std::string gaitFolder(const StudyPoint& point, const std::string& dir) {
  return dir + "/runs/" + point.folder;
}

bool solved(const StudyPoint& point, const std::string& dir) {
  return costOf(gaitFolder(point, dir)).has_value();
}

void solvePoint(const StudyConfig& c, const std::vector<StudyPoint>& points, std::size_t i,
                const std::string& dir, const StudyTools& t) {
  const StudyPoint& p = points[i];
  const std::string out = gaitFolder(p, dir);
  using Warm = StudyConfig::WarmStart;
  const bool warm = c.warm_start != Warm::kNone && p.previous && solved(points[*p.previous], dir);
  const bool done = fs::exists(out + "/summary.json") || fs::exists(out + ".failed/summary.json");
  if (warm && c.warm_start == Warm::kPreviousOnly) {  // the guess only when that optimum failed
    if (!done) solveFrom(p, points[*p.previous], dir, out, t);
    if (ended(out)) io::writeFileAtomically(out + ".start", points[*p.previous].folder);
    return;
  }
  if (!done) runTool(t, solveArgs(p), out, "solve " + p.folder);
  // The .start file is written last: without it the warm solve is still to do. A solve from the
  // guess that did not end is redone first, or the warm one would stand in for it for good.
  if (warm && ended(out) && !fs::exists(out + ".start")) warmSolve(p, points[*p.previous], dir, t);
}

namespace {

/// The numeric columns of solves.csv beside the summary.json entry each one reads, in order:
/// one list, so that a column and its entry cannot drift apart.
struct SummaryColumn {
  const char* column;
  const char* pointer;
};
constexpr SummaryColumn kSummaryColumns[] = {
    {"iterations", "/iterations"},
    {"cost", "/cost"},
    {"wall_time_s", "/wall_time_s"},
    {"factorizations", "/kkt/factorizations"},
    {"mumps_fallbacks", "/kkt/mumps_fallbacks"},
    {"inertia_corrections", "/kkt/inertia_corrections"},
    {"pivoting_factorizations", "/kkt/pivoting_factorizations"},
    {"max_torso_lean_deg", "/posture_deg/max_torso_lean"},
    {"max_stance_knee_flexion_deg", "/posture_deg/max_stance_knee_flexion"},
    {"max_swing_knee_flexion_deg", "/posture_deg/max_swing_knee_flexion"},
    {"min_normal_force_between_N", "/between_nodes/min_normal_force"},
    {"min_foot_cop_margin_between_m", "/between_nodes/min_foot_cop_margin"},
    {"max_friction_ratio_between", "/between_nodes/max_friction_ratio"},
    {"max_dsp_tip_drift_between_m", "/between_nodes/max_dsp_tip_drift"},
    {"max_rate_mismatch_between", "/between_nodes/max_rate_mismatch"},
    {"max_acceleration_mismatch_between", "/between_nodes/max_acceleration_mismatch"},
    {"strike_normal_velocity_m_s", "/strike/normal_velocity"},
    {"impulse_trailing_cone_ratio", "/strike/impulse_trailing_cone_ratio"}};

}  // namespace

std::vector<std::string> solveColumns() {
  std::vector<std::string> columns = {"status", "converged"};
  for (const SummaryColumn& c : kSummaryColumns) columns.emplace_back(c.column);
  columns.insert(columns.end(), {"start", "folder"});
  return columns;
}

std::vector<std::string> solveRow(const StudyPoint& point, const std::string& dir) {
  std::string folder = gaitFolder(point, dir);
  if (!fs::exists(folder + "/summary.json")) folder += ".failed";
  const auto s = readSummary(folder);
  std::vector<std::string> row(solveColumns().size());
  row[0] = s ? s->value("status", std::string("?")) : "no summary";
  row.back() = point.folder;
  if (!s) return row;
  row[1] = s->value("converged", true) ? "1" : "0";
  for (std::size_t k = 0; k < std::size(kSummaryColumns); ++k)
    row[2 + k] = numberText(*s, Pointer(kSummaryColumns[k].pointer));
  std::ifstream start(gaitFolder(point, dir) + ".start");
  std::string& from = row[row.size() - 2];
  if (!std::getline(start, from)) from = "guess";
  return row;
}

}  // namespace gaitopt::study
