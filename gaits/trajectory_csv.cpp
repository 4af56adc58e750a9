#include "gaits/trajectory_csv.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string_view>
#include <system_error>
#include <vector>

#include <fmt/format.h>

#include "config/config_error.hpp"
#include "dynamics/joint_coordinates.hpp"
#include "dynamics/kinematics.hpp"
#include "gaits/metrics.hpp"
#include "gaits/physical_joints.hpp"
#include "gaits/trajectory_columns.hpp"
#include "io/checked_write.hpp"

namespace gaitopt::gaits {
namespace {

using config::ConfigError;

/// q and dq are redundant with theta and dtheta (Mu 2.41); a file whose copies disagree by more
/// than this was edited by hand or written for another convention [rad, rad/s].
constexpr double kDerivedTolerance = 1e-9;

/// The header in the short form used in error messages.
std::string headerSummary(int n) {
  return fmt::format(
      "t,phase,theta1..theta{0},dtheta1..dtheta{0},ddtheta1..ddtheta{0},q0..q{1},dq0..dq{1},"
      "tau0..tau{1},fb_x,fb_y,fe_x,fe_y,zmp_x,hip_x,hip_y,swing_x,swing_y,com_x,com_y, then the "
      "physical joints' angles, rates (d...) and torques (tau_...)",
      n, n - 1);
}

// ---------------------------------------------------------------------------------------------
// Writing

void appendNumber(fmt::memory_buffer& buf, double value) {
  fmt::format_to(std::back_inserter(buf), ",{:.17g}", value);  // 17 digits: exact round trip
}

void appendNumbers(fmt::memory_buffer& buf, const Eigen::Ref<const Eigen::VectorXd>& values) {
  for (Eigen::Index i = 0; i < values.size(); ++i) appendNumber(buf, values(i));
}

void appendRow(fmt::memory_buffer& buf, const Knot& knot, const dynamics::Model& model,
               const std::vector<PhysicalJoint>& joints, double step_length) {
  fmt::format_to(std::back_inserter(buf), "{:.17g},{}", knot.t, toString(knot.phase));
  appendNumbers(buf, rowNumbers(knot, model, joints, step_length));
  buf.push_back('\n');
}

/// Writes to path.tmp and renames, so a reader never sees a half-written file.
void writeAtomically(const std::string& path, const fmt::memory_buffer& buf) {
  io::writeFileAtomically(path, std::string_view(buf.data(), buf.size()));
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

/// A field quoted for an error message, shortened so a corrupt line cannot flood the terminal.
std::string quotedField(std::string_view text) {
  constexpr size_t kMax = 40;
  return text.size() <= kMax ? fmt::format("'{}'", text)
                             : fmt::format("'{}...'", text.substr(0, kMax - 3));
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

/// Reads the fields of one data row in column order, naming file, line and column on error.
class RowParser {
 public:
  RowParser(const std::string& path, int line, const std::vector<std::string>& names,
            std::vector<std::string_view> fields)
      : path_(path), line_(line), names_(names), fields_(std::move(fields)) {
    if (fields_.size() != names_.size())
      throw ConfigError(
          path_, "", line_,
          fmt::format("expected {} comma-separated fields (one per header column), found {}{}",
                      names_.size(), fields_.size(),
                      fields_.size() < names_.size() ? " (truncated line?)" : ""));
  }

  double number() {
    const double value = current();
    ++next_;
    return value;
  }

  Eigen::VectorXd numbers(int n) {
    Eigen::VectorXd v(n);
    for (int i = 0; i < n; ++i) v(i) = number();
    return v;
  }

  Phase phase() {
    const std::string_view text = fields_[next_];
    if (text != "SSP" && text != "DSP")
      fail(fmt::format("unknown phase {}, expected SSP or DSP", quotedField(text)));
    ++next_;
    return text == "SSP" ? Phase::kSsp : Phase::kDsp;
  }

  /// Reads redundant columns that must equal `expected` (e.g. q = M theta).
  void derived(const VecD& expected, const char* relation) {
    for (int i = 0; i < expected.size(); ++i) {
      const double value = current();
      if (std::abs(value - expected(i)) > kDerivedTolerance)
        fail(fmt::format("{:.17g} disagrees with {} = {:.17g} (tolerance {})", value, relation,
                         expected(i), kDerivedTolerance));
      ++next_;
    }
  }

  /// Throws a ConfigError about the current column.
  [[noreturn]] void fail(const std::string& message) const {
    throw ConfigError(path_, names_[next_], line_, message);
  }

 private:
  /// The current field as a finite number; from_chars is locale-independent and strict (no
  /// spaces, no leading '+', the whole field must be consumed).
  double current() const {
    const std::string_view text = fields_[next_];
    double value = 0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || ec != std::errc() || end != text.data() + text.size())
      fail(fmt::format("expected a number, found {}", quotedField(text)));
    if (!std::isfinite(value)) fail(fmt::format("non-finite value {}", quotedField(text)));
    return value;
  }

  const std::string& path_;
  int line_;
  const std::vector<std::string>& names_;
  std::vector<std::string_view> fields_;
  size_t next_ = 0;
};

struct Row {
  Knot knot;
  double swing_x = 0;
};

Row parseRow(RowParser& row, const dynamics::Model& model,
             const std::vector<PhysicalJoint>& joints) {
  const int n = model.nLinks();
  Row out;
  Knot& k = out.knot;
  k.t = row.number();
  k.phase = row.phase();
  k.theta = row.numbers(n);
  k.dtheta = row.numbers(n);
  k.ddtheta = row.numbers(n);
  const VecD q = dynamics::toJoint(VecD(k.theta)), dq = dynamics::toJoint(VecD(k.dtheta));
  row.derived(q, "M theta (Mu 2.41)");
  row.derived(dq, "M dtheta (Mu 2.41)");
  k.tau = row.numbers(n);
  k.force_stance = row.numbers(2);
  k.force_swing = row.numbers(2);
  row.numbers(3);  // zmp_x, hip_x, hip_y: outputs for controllers, recomputed when writing
  out.swing_x = row.number();
  row.numbers(3);  // swing_y, com_x, com_y
  row.derived(physicalValues(joints, q, true), "the physical joint of q");
  row.derived(physicalValues(joints, dq, false), "the physical joint rate of dq");
  row.derived(physicalValues(joints, VecD(k.tau), false), "the physical joint torque of tau");
  return out;
}

}  // namespace

void writeTrajectoryCsv(const Trajectory& traj, const dynamics::Model& model,
                        const std::string& path) {
  if (traj.knots().empty())
    throw std::invalid_argument(fmt::format("cannot write an empty trajectory to '{}'", path));
  if (traj.nLinks() != model.nLinks())
    throw std::invalid_argument(fmt::format("trajectory has {} links but robot '{}' has {}",
                                            traj.nLinks(), model.name(), model.nLinks()));
  fmt::memory_buffer buf;
  const std::vector<std::string> names = columnNames(model);
  fmt::format_to(std::back_inserter(buf), "{}\n", fmt::join(names, ","));
  const std::vector<PhysicalJoint> joints = physicalJoints(model);
  for (const Knot& knot : traj.knots()) appendRow(buf, knot, model, joints, traj.stepLength());
  writeAtomically(path, buf);
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

  const std::vector<PhysicalJoint> joints = physicalJoints(model);
  std::vector<Knot> knots;
  double step_length = 0;
  for (size_t i = 1; i < lines.size(); ++i) {
    const int line = static_cast<int>(i) + 1;
    RowParser parser(path, line, names, splitFields(lines[i]));
    Row row = parseRow(parser, model, joints);
    if (!knots.empty() && row.knot.t < knots.back().t)
      throw ConfigError(path, "t", line,
                        fmt::format("time {:.17g} is before the previous row's {:.17g}; rows "
                                    "must be sorted by time",
                                    row.knot.t, knots.back().t));
    step_length = row.swing_x;  // the last row's swing tip: E at touchdown (header doc)
    knots.push_back(std::move(row.knot));
  }
  try {
    return Trajectory(model.name(), step_length, std::move(knots));
  } catch (const std::invalid_argument& e) {
    throw ConfigError(
        path, "", 0,
        fmt::format("rows do not form a trajectory: {} (knot k is on line k + 2)", e.what()));
  }
}

}  // namespace gaitopt::gaits
