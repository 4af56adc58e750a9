#include "library/library_config.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>

#include <fmt/format.h>

#include "config/config_error.hpp"
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
  const int count = static_cast<int>(r.number("count", [](double v) {
    return v >= 1 && v <= 1000 && v == std::floor(v) ? "" : "an integer in [1, 1000]";
  }));
  if (count > 1 && !(to > from)) r.fail("to", fmt::format("expected a number > from ({:g})", from));
  std::vector<double> values;
  for (int k = 0; k < count; ++k)
    values.push_back(count == 1 ? from : from + (to - from) * k / (count - 1));
  return values;
}

std::vector<double> readAxis(const YamlReader& grid, const std::string& key,
                             const NumberCheck& check, double base) {
  if (!grid.has(key)) return {base};
  std::vector<double> v =
      grid.isMap(key) ? readRange(grid.map(key), check) : grid.numbers(key, check);
  std::sort(v.begin(), v.end());
  if (std::adjacent_find(v.begin(), v.end()) != v.end())
    grid.fail(key, "expected distinct values, got one twice");
  return v;
}

}  // namespace

std::array<double, 3> basePoint(const ocp::OcpConfig& base) {
  double duration = 0;
  for (const auto& phase : base.phases) duration += phase.duration;
  return {base.step_length / duration, base.step_length, base.slope};
}

LibraryConfig loadLibraryConfig(const std::string& path,
                                const std::vector<config::Override>& overrides) {
  const auto root = YamlReader::fromFile(path, overrides);
  root.allowOnly({"name", "description", "ocp", "grid"});
  LibraryConfig c;
  c.name = root.string("name");
  root.stringOr("description", "");
  c.path = path;
  c.ocp_path = (std::filesystem::path(path).parent_path() / root.string("ocp")).string();
  c.base = ocp::loadOcpConfig(c.ocp_path);
  const std::array<double, 3> base = basePoint(c.base);
  const auto grid = root.map("grid");
  grid.allowOnly({"speed", "step_length", "slope"});
  c.axes[kSpeed] = readAxis(grid, "speed", config::inRange(0.01, 10.0, "[m/s]"), base[kSpeed]);
  c.axes[kStepLength] =
      readAxis(grid, "step_length", config::inRange(0.01, 5.0, "[m]"), base[kStepLength]);
  c.axes[kSlope] = readAxis(grid, "slope", config::angleInRange(-0.35, 0.35), base[kSlope]);
  return c;
}

}  // namespace gaitopt::library
