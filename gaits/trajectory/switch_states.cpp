#include "gaits/trajectory/switch_states.hpp"

#include <filesystem>
#include <system_error>

#include <fmt/format.h>

#include "config/config_error.hpp"
#include "gaits/trajectory/trajectory_columns.hpp"
#include "io/strict_json.hpp"

namespace gaitopt::gaits {
namespace {

using config::ConfigError;
using nlohmann::ordered_json;

/// One knot as a trajectory.csv row object, column name -> value.
ordered_json rowJson(const Knot& knot, const std::vector<std::string>& names,
                     const dynamics::Model& model, const std::vector<PhysicalJoint>& joints,
                     double step_length) {
  const Eigen::VectorXd numbers = rowNumbers(knot, model, joints, step_length);
  ordered_json row = {{"t", knot.t}, {"phase", toString(knot.phase)}};
  for (Eigen::Index i = 0; i < numbers.size(); ++i)
    row[names[static_cast<size_t>(i) + 2]] = numbers(i);
  return row;
}

/// The row object at `key` read as a CSV row: each value turned into its field text (numbers
/// with 17 digits, exact), so the CSV's checks apply.
Row readRowJson(const std::string& path, const std::string& key, const ordered_json& row,
                const std::vector<std::string>& names, const dynamics::Model& model,
                const std::vector<PhysicalJoint>& joints) {
  if (!row.is_object()) throw ConfigError(path, key, 0, "expected a trajectory.csv row object");
  std::vector<std::string> texts;
  for (const auto& name : names) {
    if (!row.contains(name)) throw ConfigError(path, key + "." + name, 0, "missing column");
    const auto& value = row[name];
    texts.push_back(value.is_string()   ? value.get<std::string>()
                    : value.is_number() ? fmt::format("{:.17g}", value.get<double>())
                                        : value.dump());
  }
  const std::vector<std::string_view> fields(texts.begin(), texts.end());
  return parseRow({path, 0, key + "."}, names, fields, model, joints);
}

}  // namespace

ordered_json switchStatesJson(const GridExport& grid, const dynamics::Model& model) {
  const std::vector<std::string> names = columnNames(model);
  const std::vector<PhysicalJoint> joints = physicalJoints(model);
  const auto row = [&](const Knot& k) {
    return rowJson(k, names, model, joints, grid.step_length);
  };
  ordered_json switches = ordered_json::array();
  for (const PhaseSwitch& s : grid.switches)
    switches.push_back({{"t", s.before.t},
                        {"from", toString(s.before.phase)},
                        {"to", toString(s.after.phase)},
                        {"before", row(s.before)},
                        {"after", row(s.after)}});
  return {
      {"sample_rate_hz", grid.rate_hz}, {"phase_switches", switches}, {"step_end", row(grid.end)}};
}

std::optional<SwitchStates> readSwitchStates(const std::string& path,
                                             const dynamics::Model& model) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return std::nullopt;
  const ordered_json summary = io::readStrictJson(path);
  if (!summary.is_object() || !summary.contains("phase_switches")) return std::nullopt;
  const auto& list = summary["phase_switches"];
  if (!list.is_array()) throw ConfigError(path, "phase_switches", 0, "expected a list");
  if (!summary.contains("step_end"))
    throw ConfigError(path, "step_end", 0,
                      "missing: the state at the end of the step goes with phase_switches");
  const auto& rate = summary.value("sample_rate_hz", ordered_json());
  if (!rate.is_number() || !(rate.get<double>() > 0))
    throw ConfigError(path, "sample_rate_hz", 0,
                      fmt::format("expected the sample rate [Hz] (> 0) that goes with "
                                  "phase_switches, got {}",
                                  rate.dump()));
  const std::vector<std::string> names = columnNames(model);
  const std::vector<PhysicalJoint> joints = physicalJoints(model);
  const auto read = [&](const std::string& key, const ordered_json& row) {
    return readRowJson(path, key, row, names, model, joints);
  };
  SwitchStates out{rate.get<double>(), {}, read("step_end", summary["step_end"])};
  for (size_t i = 0; i < list.size(); ++i) {
    const std::string key = fmt::format("phase_switches[{}]", i);
    if (!list[i].is_object()) throw ConfigError(path, key, 0, "expected an object");
    PhaseSwitch s{read(key + ".before", list[i].value("before", ordered_json())).knot,
                  read(key + ".after", list[i].value("after", ordered_json())).knot};
    if (s.before.t != s.after.t || s.before.phase != Phase::kSsp || s.after.phase != Phase::kDsp)
      throw ConfigError(
          path, key, 0,
          fmt::format("before is {} at t = {}, after {} at t = {}: expected SSP "
                      "then DSP at one time",
                      toString(s.before.phase), s.before.t, toString(s.after.phase), s.after.t));
    out.switches.push_back(std::move(s));
  }
  return out;
}

}  // namespace gaitopt::gaits
