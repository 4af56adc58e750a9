#include "library/library_config.hpp"

#include <algorithm>
#include <filesystem>

#include <fmt/format.h>

#include "config/config_error.hpp"
#include "config/config_path.hpp"
#include "config/yaml_reader.hpp"

namespace gaitopt::library {
namespace {

using config::NumberCheck;
using config::YamlReader;

/// A range {from, to, count}: `count` evenly spaced values from `from` to `to`.
std::vector<double> readRange(const YamlReader& r, const NumberCheck& check) {
  r.allowOnly({"from", "to", "count"});
  const double from = r.number("from", check);
  const double to = r.number("to", check);
  const int count = static_cast<int>(r.number("count", config::wholeInRange(1, 1000, "")));
  if (count > 1 && !(to > from)) r.fail("to", fmt::format("expected a number > from ({:g})", from));
  std::vector<double> values;
  for (int k = 0; k < count; ++k)
    values.push_back(count == 1 ? from : from + (to - from) * k / (count - 1));
  return values;
}

bool isRange(const YamlReader& grid, const std::string& key) {
  if (!grid.isMap(key)) return false;
  const auto keys = grid.map(key).keys();
  return std::any_of(keys.begin(), keys.end(),
                     [](const std::string& k) { return k == "from" || k == "to" || k == "count"; });
}

std::vector<double> readValues(const YamlReader& grid, const std::string& key,
                               const NumberCheck& check) {
  std::vector<double> v =
      isRange(grid, key) ? readRange(grid.map(key), check) : grid.numbers(key, check);
  std::sort(v.begin(), v.end());
  if (std::adjacent_find(v.begin(), v.end()) != v.end())
    grid.fail(key, "expected distinct values, got one twice");
  return v;
}

std::vector<double> readAxis(const YamlReader& grid, const std::string& key,
                             const NumberCheck& check, double base) {
  return grid.has(key) ? readValues(grid, key, check) : std::vector<double>{base};
}

bool isWalkAxis(const std::string& key) {
  return std::find(kAxisNames.begin(), kAxisNames.end(), key) != kAxisNames.end();
}

/// Keys the walk's axes set at every point (point_problem.hpp): an axis over them would be
/// overwritten.
bool setByWalkAxes(const std::string& key) {
  const std::string last = key.substr(key.find_last_of('.') + 1);
  return isWalkAxis(key) || key == "step_duration" || last.rfind("duration", 0) == 0;
}

config::Override overrideOf(const std::string& key, double value) {
  return {key, fmt::format("{}", value)};
}

/// Every value of a config axis loads as the OCP file would with it.
void checkConfigAxis(const YamlReader& grid, const std::string& grid_key, const GridAxis& axis,
                     const std::string& ocp_path) {
  if (setByWalkAxes(axis.key))
    grid.fail(grid_key,
              "the walk's own axes set this key at every point: use grid.speed, "
              "grid.step_length or grid.slope");
  for (double v : axis.values) try {
      ocp::loadOcpConfig(ocp_path, {overrideOf(axis.key, v)});
    } catch (const config::ConfigError& e) {
      grid.fail(grid_key, fmt::format("the base problem refuses {:g} here: {}", v, e.what()));
    }
}

/// The grid's config keys, in file order: a nested mapping that is not a range names a key path
/// (`constraints: {friction_margin: [...]}` is `constraints.friction_margin`), as --set spells it.
void readConfigAxes(const YamlReader& grid, const std::string& prefix, LibraryConfig& c) {
  for (const std::string& key : grid.keys()) {
    const std::string path = prefix.empty() ? key : prefix + "." + key;
    if (prefix.empty() && isWalkAxis(key)) continue;
    if (grid.isMap(key) && !isRange(grid, key)) {
      readConfigAxes(grid.map(key), path, c);
      continue;
    }
    // `constraints.x: [...]` beside `constraints: {x: [...]}` name one key twice.
    if (std::any_of(c.config_axes.begin(), c.config_axes.end(),
                    [&](const GridAxis& a) { return a.key == path; }))
      grid.fail(key, fmt::format("the key {} is given twice (once dotted, once nested)", path));
    GridAxis axis{path, readValues(grid, key, [](double) { return std::string(); })};
    checkConfigAxis(grid, key, axis, c.ocp_path);
    c.config_axes.push_back(std::move(axis));
  }
}

double fileValue(const std::string& ocp_path, const GridAxis& axis) {
  const YAML::Node v = config::valueAt(YAML::LoadFile(ocp_path), axis.key);
  double value = 0;
  // A key left to its default, or set to a word ("optimize"), has no number to start from.
  return v.IsScalar() && YAML::convert<double>::decode(v, value)
             ? value
             : axis.values[axis.values.size() / 2];
}

}  // namespace

std::array<double, kWalkAxes> basePoint(const ocp::OcpConfig& base) {
  double duration = 0;
  for (const auto& phase : base.phases) duration += phase.duration;
  return {base.step_length / duration, base.step_length, base.slope};
}

std::vector<double> basePoint(const LibraryConfig& c) {
  const auto walk = basePoint(c.base);
  std::vector<double> values(walk.begin(), walk.end());
  values.insert(values.end(), c.config_base.begin(), c.config_base.end());
  return values;
}

ocp::OcpConfig baseAt(const LibraryConfig& c, const GridPoint& point) {
  if (c.config_axes.empty()) return c.base;
  std::vector<config::Override> overrides;
  for (std::size_t a = 0; a < c.config_axes.size(); ++a)
    overrides.push_back(overrideOf(c.config_axes[a].key, point.values[kWalkAxes + a]));
  return ocp::loadOcpConfig(c.ocp_path, overrides);
}

LibraryConfig loadLibraryConfig(const std::string& path,
                                const std::vector<config::Override>& overrides) {
  const auto root = YamlReader::fromFile(path, overrides);
  root.allowOnly({"name", "description", "ocp", "grid"});
  LibraryConfig c;
  c.name = root.string("name");
  root.stringOr("description", "");
  c.path = path;
  c.ocp_path = config::besideConfig(path, root.string("ocp"));
  c.base = ocp::loadOcpConfig(c.ocp_path);
  const std::array<double, kWalkAxes> base = basePoint(c.base);
  const auto grid = root.map("grid");
  c.axes[kSpeed] = readAxis(grid, "speed", config::inRange(0.01, 10.0, "[m/s]"), base[kSpeed]);
  c.axes[kStepLength] =
      readAxis(grid, "step_length", config::inRange(0.01, 5.0, "[m]"), base[kStepLength]);
  c.axes[kSlope] = readAxis(grid, "slope", config::angleInRange(-0.35, 0.35), base[kSlope]);
  readConfigAxes(grid, "", c);
  for (const auto& axis : c.config_axes) c.config_base.push_back(fileValue(c.ocp_path, axis));
  return c;
}

}  // namespace gaitopt::library
