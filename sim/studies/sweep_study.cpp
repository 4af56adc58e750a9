#include "sim/studies/sweep_study.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include "config/overrides.hpp"
#include "config/quantities.hpp"
#include "io/settings_record.hpp"

namespace gaitopt::sim {

std::vector<double> sweepValues(const SweepParameter& p, const gaits::GridAxis& axis) {
  // The ends bound every value between them.
  for (const double end : {axis.first, axis.last})
    if (std::string why = config::rangeError(p.quantity, end); !why.empty())
      throw std::invalid_argument(why);
  // One rule for every sweep and map axis: a:b:n runs upwards. a == b with n > 1 would walk one
  // point n times into one row key, a > b gives the same points as b:a:n under another key, and
  // n = 1 with a != b walks a alone, dropping b without a word.
  const std::string range = fmt::format("{:g}:{:g}:{}", axis.first, axis.last, axis.count);
  if (axis.count > 1 && !(axis.first < axis.last))
    throw std::invalid_argument(
        fmt::format("'{}': {} values need a < b (a range runs upwards); one value is a or a:a:1",
                    range, axis.count));
  if (axis.count == 1 && axis.first != axis.last)
    throw std::invalid_argument(fmt::format(
        "'{}': n = 1 is one value, a, and would drop b: give n >= 2, or a alone", range));
  if (p.geometric && !(axis.first > 0 && axis.last > 0))
    throw std::invalid_argument("a geometric range needs positive ends");
  std::vector<double> values;
  for (int k = 0; k < axis.count; ++k) {
    const double v = !p.geometric || axis.count == 1
                         ? axis.value(k)
                         : axis.first * std::pow(axis.last / axis.first,
                                                 static_cast<double>(k) / (axis.count - 1));
    const double scale = std::max(std::abs(axis.first), std::abs(axis.last));
    values.push_back(std::abs(v) < 1e-12 * scale ? 0.0 : v);
    // A row is found again by its value's 10 digits (SweepFile::key): two values that share
    // them would be one row.
    if (values.size() > 1 && SweepFile::key(values.back()) == SweepFile::key(values.end()[-2]))
      throw std::invalid_argument(fmt::format(
          "'{}': the values {} and {} are closer than the 10 digits a row keeps: give fewer "
          "values or a wider range",
          range, SweepFile::key(values.end()[-2]), SweepFile::key(values.back())));
  }
  return values;
}

double keyedValue(double value) {
  return std::stod(SweepFile::key(value));
}

SweepRow walkSweepPoint(const dynamics::Model& model, const Reference& reference, Scenario scenario,
                        const std::string& name, double value) {
  setSweepValue(scenario, name, value);
  const ScenarioResult r = runScenario(model, reference, scenario);
  SweepRow row{value,       r.walk.steps_completed, scenario.steps,
               r.walk.fell, r.walk.failure,         r.walk.max_tracking_error};
  if (r.poincare && r.poincare->ok) row.max_multiplier = r.poincare->max_multiplier;
  if (r.walk.steps_completed > 0)
    row.mean_advance = completedTotals(r.walk).distance / r.walk.steps_completed;
  row.wall_time_s = r.wall_time_s;
  return row;
}

std::vector<double> withNominal(std::vector<double> values, double nominal) {
  if (!std::isfinite(nominal) || values.empty()) return values;
  const double tolerance = 1e-9 * std::max(1.0, std::abs(values.back() - values.front()));
  // Also a value of the nominal's row key: inserted, the two would share one row.
  for (const double v : values)
    if (std::abs(v - nominal) <= tolerance || SweepFile::key(v) == SweepFile::key(nominal))
      return values;
  values.insert(std::upper_bound(values.begin(), values.end(), nominal), nominal);
  return values;
}

nlohmann::ordered_json walkingInterval(const SweepParameter& parameter,
                                       const std::map<std::string, SweepRow>& by_key,
                                       double nominal) {
  std::vector<SweepRow> rows;
  for (const auto& [k, row] : by_key) rows.push_back(row);
  std::sort(rows.begin(), rows.end(),
            [](const SweepRow& a, const SweepRow& b) { return a.value < b.value; });
  const auto walks = [](const SweepRow& r) {
    return !r.fell && r.steps_completed == r.steps_requested;
  };
  nlohmann::ordered_json j{{"unit", parameter.unit()},
                           {"meaning", parameter.meaning},
                           // A geometric parameter is drawn on a log axis, also where the
                           // nominal inserted breaks its constant ratio.
                           {"geometric", parameter.geometric},
                           {"values", rows.size()},
                           {"nominal", std::isfinite(nominal) ? nlohmann::ordered_json(nominal)
                                                              : nlohmann::ordered_json()},
                           {"walks_from", nullptr},
                           {"walks_to", nullptr}};
  if (rows.empty() || !std::isfinite(nominal)) return j;
  std::size_t c = 0;  // the point nearest the nominal value
  for (std::size_t i = 1; i < rows.size(); ++i)
    if (std::abs(rows[i].value - nominal) < std::abs(rows[c].value - nominal)) c = i;
  if (!walks(rows[c])) {  // no interval: say why the nominal walk itself fails
    j["nominal_failure"] = rows[c].failure;
    return j;
  }
  std::size_t lo = c, hi = c;
  while (lo > 0 && walks(rows[lo - 1])) --lo;
  while (hi + 1 < rows.size() && walks(rows[hi + 1])) ++hi;
  // The grid's values as the CSV shows them: its doubles carry the noise of a + (b - a) k / (n - 1)
  // (friction 0.30000000000000004 in summary.json, 0.3 in the CSV).
  j["walks_from"] = keyedValue(rows[lo].value);
  j["walks_to"] = keyedValue(rows[hi].value);
  if (lo > 0)
    j["fails_below"] = {{"value", keyedValue(rows[lo - 1].value)},
                        {"failure", rows[lo - 1].failure}};
  if (hi + 1 < rows.size())
    j["fails_above"] = {{"value", keyedValue(rows[hi + 1].value)},
                        {"failure", rows[hi + 1].failure}};
  return j;
}

namespace {

/// A YAML value by content: numbers as numbers (0.10 and 0.1, 1e-3 and 0.001 alike), lists item
/// by item, mappings by key in key order, any other scalar as its text.
nlohmann::ordered_json yamlContent(const YAML::Node& node) {
  if (node.IsSequence()) {
    auto j = nlohmann::ordered_json::array();
    for (const YAML::Node& item : node) j.push_back(yamlContent(item));
    return j;
  }
  if (node.IsMap()) {
    std::map<std::string, nlohmann::ordered_json> sorted;
    for (const auto& kv : node) sorted[kv.first.Scalar()] = yamlContent(kv.second);
    auto j = nlohmann::ordered_json::object();
    for (auto& [key, value] : sorted) j[key] = std::move(value);
    return j;
  }
  if (!node.IsScalar()) return nullptr;
  double v = 0;
  if (YAML::convert<double>::decode(node, v) && std::isfinite(v)) return v;
  return node.Scalar();
}

/// Whether setting `a` and then `b` may differ from `b` then `a`: one key path holds the other
/// ("robot.foot" and "robot.foot.heel").
bool overlap(const std::string& a, const std::string& b) {
  const auto holds = [](const std::string& outer, const std::string& inner) {
    return inner.size() > outer.size() && inner.compare(0, outer.size(), outer) == 0 &&
           (inner[outer.size()] == '.' || inner[outer.size()] == '[');
  };
  return holds(a, b) || holds(b, a);
}

}  // namespace

nlohmann::ordered_json setsContent(const std::vector<std::string>& sets) {
  // The last value of a key replaces the earlier ones, as config::applyOverrides does.
  std::vector<std::pair<std::string, nlohmann::ordered_json>> kept;
  for (const config::Override& o : config::parseOverrides(sets)) {
    std::erase_if(kept, [&](const auto& k) { return k.first == o.key; });
    nlohmann::ordered_json value;
    try {
      value = yamlContent(YAML::Load(o.value));
    } catch (const YAML::Exception&) {
      value = o.value;  // the files' readers refuse it before a folder is keyed
    }
    kept.emplace_back(o.key, std::move(value));
  }
  // Order-free unless it matters (a key inside another's value): then as given.
  bool ordered = false;
  for (std::size_t i = 0; i < kept.size(); ++i)
    for (std::size_t k = 0; k < i; ++k) ordered = ordered || overlap(kept[i].first, kept[k].first);
  if (!ordered)
    std::sort(kept.begin(), kept.end(),
              [](const auto& x, const auto& y) { return x.first < y.first; });
  auto j = nlohmann::ordered_json::object();
  for (auto& [key, value] : kept) j[key] = std::move(value);
  return j;
}

nlohmann::ordered_json sweepFolderSettings(const ScenarioSettings& s, const ReferenceFolder& ref,
                                           const Scenario& base) {
  nlohmann::ordered_json j = scenarioJson(s, base);
  // Paths differ between machines and say nothing of what they held: the bytes are keyed.
  j.erase("reference");
  j.erase("ground_file");
  j["robot"] = ref.model.name();
  j["robot_file_fnv1a"] = io::fileFingerprint(ref.robot_path);
  j["reference_trajectory_fnv1a"] = io::fileFingerprint(ref.dir + "/trajectory.csv");
  // summary.json carries the switch states and the slope the reference is walked with; the
  // same gait solved again (another wall time) walks the same rows.
  const std::string summary = ref.dir + "/summary.json";
  j["reference_summary_fnv1a"] =
      std::filesystem::exists(summary) ? io::summaryFingerprint(summary) : "(absent)";
  j["ground_file_fnv1a"] = io::fileFingerprint(groundPath(s.ground));
  j["friction"] = s.friction;
  j["poincare"] = base.poincare;
  // By content, not as typed: a rerun with its --set reordered or written otherwise (0.10 for
  // 0.1, 1e-3 for 0.001) walks the same rows (summary.json keeps the text).
  if (!s.sets.empty()) j["config_overrides"] = setsContent(s.sets);
  return j;
}

}  // namespace gaitopt::sim
