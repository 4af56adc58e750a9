#include "gaits/trajectory/trajectory_csv.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string_view>
#include <system_error>
#include <vector>

#include <fmt/format.h>

#include "config/config_error.hpp"
#include "gaits/trajectory/grid_export.hpp"
#include "gaits/trajectory/physical_joints.hpp"
#include "gaits/trajectory/switch_states.hpp"
#include "gaits/trajectory/trajectory_columns.hpp"
#include "gaits/trajectory/trajectory_row.hpp"
#include "io/output/checked_write.hpp"

namespace gaitopt::gaits {
namespace {

using config::ConfigError;

/// How far a row's time may be from i / rate in a file on the grid: times are written exactly, so
/// only a file edited by hand misses by more [s].
constexpr double kGridTolerance = 1e-12;

/// The header in the short form used in error messages.
std::string headerSummary(int n) {
  return fmt::format(
      "t,phase,theta1..theta{0},dtheta1..dtheta{0},ddtheta1..ddtheta{0},q0..q{1},dq0..dq{1},"
      "tau0..tau{1},fb_x,fb_y,fe_x,fe_y,zmp_x,hip_x,hip_y,swing_x,swing_y,com_x,com_y, then the "
      "physical joints' angles, rates (d...) and torques (tau_...)",
      n, n - 1);
}

// ---------------------------------------------------------------------------------------------
// Reading

std::vector<std::string> readLines(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw ConfigError(path, "", 0, "trajectory file not found or not a regular file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw ConfigError(path, "", 0, "cannot open the trajectory file");
  std::vector<std::string> lines;
  for (std::string line; std::getline(in, line);) {
    if (!line.empty() && line.back() == '\r') line.pop_back();  // tolerate CRLF line ends
    lines.push_back(std::move(line));
  }
  if (in.bad()) throw ConfigError(path, "", 0, "read error in the trajectory file");
  return lines;
}

std::vector<std::string_view> splitFields(std::string_view line) {
  std::vector<std::string_view> fields;
  for (size_t start = 0;;) {
    const size_t comma = line.find(',', start);
    fields.push_back(line.substr(start, comma - start));
    if (comma == std::string_view::npos) return fields;
    start = comma + 1;
  }
}

/// Number of links a header is written for (count of theta<i> columns).
int linksInHeader(const std::vector<std::string>& fields) {
  return static_cast<int>(std::count_if(fields.begin(), fields.end(), [](const std::string& f) {
    return f.rfind("theta", 0) == 0 && f.size() > 5 &&
           std::all_of(f.begin() + 5, f.end(), [](char c) { return c >= '0' && c <= '9'; });
  }));
}

/// Names the first column where the header departs from `expected` and says what was expected.
ConfigError headerMismatch(const std::string& path, const std::vector<std::string>& found,
                           const std::vector<std::string>& expected, int n) {
  const auto [f, e] = std::mismatch(found.begin(), found.end(), expected.begin(), expected.end());
  const auto i = static_cast<size_t>(f - found.begin());
  const std::string format = fmt::format("(expected {})", headerSummary(n));
  if (e != expected.end() && std::equal(f, found.end(), e + 1, expected.end()))
    return ConfigError(
        path, *e, 1,
        fmt::format("missing column (column {} should be '{}') {}", i + 1, *e, format));
  if (f != found.end() && std::equal(f + 1, found.end(), e, expected.end()))
    return ConfigError(path, *f, 1, fmt::format("unexpected column {} {}", i + 1, format));
  if (e == expected.end())
    return ConfigError(path, *f, 1,
                       fmt::format("unexpected extra columns from column {} on {}", i + 1, format));
  if (f == found.end())
    return ConfigError(path, *e, 1,
                       fmt::format("missing column {} and those after it {}", i + 1, format));
  return ConfigError(
      path, *e, 1,
      fmt::format("column {} is {}, expected '{}' {}", i + 1, quotedField(*f), *e, format));
}

void checkHeader(const std::string& path, const std::string& line, const dynamics::Model& model,
                 const std::vector<std::string>& expected) {
  const int n = model.nLinks();
  std::vector<std::string> found;
  for (const auto field : splitFields(line)) found.emplace_back(field);
  if (found == expected) return;
  const int n_file = linksInHeader(found);
  const std::vector<std::string> mu = muColumnNames(n_file);
  if (n_file != n && found.size() >= mu.size() && std::equal(mu.begin(), mu.end(), found.begin()))
    throw ConfigError(path, "", 1,
                      fmt::format("the file has columns for {} links (theta1..theta{}) but robot "
                                  "'{}' has {} links",
                                  n_file, n_file, model.name(), n));
  throw headerMismatch(path, found, expected, n);
}

/// The data rows' knots in file order and the last row's swing_x: the step length of a file
/// that ends at the period (E at touchdown, or pinned there through the DSP).
struct DataRows {
  std::vector<Knot> knots;
  double last_swing_x = 0;
};

DataRows dataRows(const std::string& path, const std::vector<std::string>& lines,
                  const std::vector<std::string>& names, const dynamics::Model& model) {
  const std::vector<PhysicalJoint> joints = physicalJoints(model);
  DataRows out;
  for (size_t i = 1; i < lines.size(); ++i) {
    const int line = static_cast<int>(i) + 1;
    Row row = parseRow({path, line, ""}, names, splitFields(lines[i]), model, joints);
    if (!out.knots.empty() && row.knot.t < out.knots.back().t)
      throw ConfigError(path, "t", line,
                        fmt::format("time {:.17g} is before the previous row's {:.17g}; rows "
                                    "must be sorted by time",
                                    row.knot.t, out.knots.back().t));
    out.last_swing_x = row.swing_x;
    out.knots.push_back(std::move(row.knot));
  }
  return out;
}

/// Rows with switch states must be the whole grid t_i = i / rate up to the step's end: a file
/// cut short or edited would otherwise be read as a step that jumps from its last row to the
/// stored end state. Rows are numbered as in the file (row i on line i + 2).
void checkGrid(const std::string& path, const std::vector<Knot>& rows, const SwitchStates& s) {
  const double span = s.end.knot.t * s.rate_hz;  // N plus a fraction; any number in a bad file
  const bool plausible = span >= 0 && span < static_cast<double>(rows.size()) + 1;
  if (!plausible || rows.size() != gridSize(s.end.knot.t, s.rate_hz))
    throw ConfigError(path, "", 0,
                      fmt::format("{} row(s) on the grid, but t_i = i / {} Hz up to the step's "
                                  "end at {} s (summary.json) makes {:.0f}: a truncated or "
                                  "edited file",
                                  rows.size(), s.rate_hz, s.end.knot.t, std::floor(span) + 1));
  for (size_t i = 0; i < rows.size(); ++i)
    if (std::abs(rows[i].t - static_cast<double>(i) / s.rate_hz) > kGridTolerance)
      throw ConfigError(path, "t", static_cast<int>(i) + 2,
                        fmt::format("time {:.17g} is not i / rate = {} / {} Hz (summary.json)",
                                    rows[i].t, i, s.rate_hz));
}

/// The summary.json in the folder of `path`, where a gait folder keeps its switch states.
std::string summaryBeside(const std::string& path) {
  return (std::filesystem::path(path).parent_path() / "summary.json").string();
}

}  // namespace

void writeTrajectoryCsv(const TrajectoryText& text, const std::string& path) {
  const std::string header = fmt::format("{}\n", fmt::join(text.names(), ","));
  io::writeFileAtomically(path, header + text.csvLines());  // no reader sees a half-written file
}

void writeTrajectoryCsv(const std::vector<Knot>& rows, double step_length,
                        const dynamics::Model& model, const std::string& path) {
  writeTrajectoryCsv(TrajectoryText(rows, step_length, model), path);
}

Trajectory readTrajectoryCsv(const std::string& path, const dynamics::Model& model) {
  const std::vector<std::string> lines = readLines(path);
  const int n = model.nLinks();
  if (lines.empty())
    throw ConfigError(path, "", 0,
                      fmt::format("empty file, expected the header {}", headerSummary(n)));
  const std::vector<std::string> names = columnNames(model);
  checkHeader(path, lines.front(), model, names);
  if (lines.size() < 2) throw ConfigError(path, "", 1, "no data rows after the header");
  DataRows rows = dataRows(path, lines, names, model);
  const auto states = readSwitchStates(summaryBeside(path), model);
  if (states) checkGrid(path, rows.knots, *states);
  try {
    if (states)
      return joinGrid(model.name(), states->end.swing_x, rows.knots, states->switches,
                      states->end.knot);
    return Trajectory(model.name(), rows.last_swing_x, std::move(rows.knots));
  } catch (const std::invalid_argument& e) {
    throw ConfigError(
        path, "", 0,
        fmt::format("rows do not form a trajectory: {} ({})", e.what(),
                    states ? "with the switch states of the summary.json beside it"
                           : "knot k is on line k + 2; rows on one fixed-rate grid need the "
                             "phase_switches of the summary.json beside them"));
  }
}

}  // namespace gaitopt::gaits
