#include "study/study_config.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <optional>

#include <fmt/format.h>

#include "config/config_path.hpp"
#include "config/yaml_reader.hpp"
#include "io/data_dir.hpp"
#include "ocp/problem/ocp_config.hpp"
#include "sim/controllers/controller_registry.hpp"

namespace gaitopt::study {
namespace {

using config::YamlReader;
namespace fs = std::filesystem;

/// The scenario options of `gaitopt simulate` and `gaitopt stability` a study may set.
const std::vector<std::string> kScenarioOptions = {
    "ground",     "cop-limit",    "steps",    "robot",      "uncertainty-on", "uncertainty-case",
    "mass-error", "length-error", "friction", "gain-scale", "max-slip",       "restitution"};

/// A label is a folder-name part: letters, digits and . _ + - only.
bool plainLabel(const std::string& text) {
  return !text.empty() && std::all_of(text.begin(), text.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) != 0 ||
           std::string("._+-").find(c) != std::string::npos;
  });
}

/// "phases[0].segments" is "segments".
std::string columnName(const std::string& key) {
  const std::string last = key.substr(key.find_last_of('.') + 1);
  return last.substr(0, last.find('['));
}

/// `key: K, values: [...]`: one key, each value its YAML text, labelled by itself by default.
StudyAxis keyAxis(const YamlReader& r) {
  const std::string key = r.string("key");
  StudyAxis axis{r.stringOr("name", columnName(key)), {}, {}};
  for (const std::string& value : r.yamlTexts("values")) {
    axis.values.push_back({{key, value}});
    axis.labels.push_back(value);
  }
  return axis;
}

/// `name: N, values: [{K: V, ...}, ...], labels: [...]`: several keys set together per value.
StudyAxis setsAxis(const YamlReader& r) {
  StudyAxis axis{r.string("name"), {}, {}};
  for (const YamlReader& item : r.list("values")) {
    std::vector<config::Override> sets;
    for (const std::string& key : item.keys()) sets.push_back({key, item.yamlText(key)});
    axis.values.push_back(std::move(sets));
  }
  if (!r.has("labels")) r.fail("labels", "an axis of several keys needs a label per value");
  return axis;
}

/// The first of `names` given twice, if any.
std::optional<std::string> givenTwice(const std::vector<std::string>& names) {
  for (std::size_t i = 0; i < names.size(); ++i)
    if (std::find(names.begin() + i + 1, names.end(), names[i]) != names.end()) return names[i];
  return std::nullopt;
}

/// Every value loads with every gait (with its sets) as `--set` would load it.
void checkValues(const YamlReader& r, const StudyAxis& axis, const std::vector<StudyGait>& gaits) {
  for (std::size_t i = 0; i < axis.values.size(); ++i) {
    if (!plainLabel(axis.labels[i]))
      r.fail(r.has("labels") ? "labels" : "values",
             fmt::format("'{}' cannot name a folder: give labels of letters, digits and . _ + -",
                         axis.labels[i]));
    for (const StudyGait& gait : gaits) try {
        std::vector<config::Override> with = gait.sets;
        with.insert(with.end(), axis.values[i].begin(), axis.values[i].end());
        ocp::loadOcpConfig(gait.path, with);
      } catch (const config::ConfigError& e) {
        r.fail("values", fmt::format("{} refuses '{}': {}", gait.name, axis.labels[i], e.what()));
      }
  }
}

StudyAxis readAxis(const YamlReader& r, const std::vector<StudyGait>& gaits) {
  r.allowOnly({"key", "name", "values", "labels"});
  StudyAxis axis = r.has("key") ? keyAxis(r) : setsAxis(r);
  if (!plainLabel(axis.name))
    r.fail("name", "expected letters, digits and . _ + - (a folder part)");
  if (r.has("labels")) axis.labels = r.yamlTexts("labels");
  if (axis.labels.size() != axis.values.size())
    r.fail("labels", fmt::format("expected one label per value ({})", axis.values.size()));
  if (const auto twice = givenTwice(axis.labels))
    r.fail(r.has("labels") ? "labels" : "values",
           fmt::format("'{}' is given twice: its points would share one folder and one result",
                       *twice));
  checkValues(r, axis, gaits);
  return axis;
}

/// The leaves of `set`, each as `--set` spells its key: `{solver: {tolerance: 1e-6}}` and
/// `{solver.tolerance: 1e-6}` both set solver.tolerance (so `--set set.solver.tolerance=...` on
/// the study config works too).
void readSets(const YamlReader& set, const std::string& prefix,
              std::vector<config::Override>& sets) {
  for (const std::string& key : set.keys()) {
    const std::string path = prefix.empty() ? key : prefix + "." + key;
    if (set.isMap(key))
      readSets(set.map(key), path, sets);
    else
      sets.push_back({path, set.yamlText(key)});
  }
}

/// A gait entry's `set`: one mapping, or a list of mappings read in order (so an anchored
/// mapping shared by several entries is followed by each entry's own values).
void readEntrySets(const YamlReader& entry, std::vector<config::Override>& sets) {
  if (entry.isMap("set")) return readSets(entry.map("set"), "", sets);
  for (const YamlReader& part : entry.list("set")) readSets(part, "", sets);
}

/// `gaits`: each a path, or `{config: PATH, name: NAME, set: {...} or [{...}, ...]}`; each loads
/// with its sets.
std::vector<StudyGait> readGaits(const YamlReader& root, const std::string& file,
                                 const std::vector<config::Override>& sets) {
  std::vector<StudyGait> gaits;
  const std::vector<std::string> texts = root.yamlTexts("gaits");
  const std::vector<std::optional<YamlReader>> maps = root.maybeMaps("gaits");
  for (std::size_t i = 0; i < texts.size(); ++i) {
    StudyGait g{"", texts[i], sets};
    if (const auto& entry = maps[i]) {
      entry->allowOnly({"config", "name", "set"});
      g.path = entry->string("config");
      g.name = entry->stringOr("name", "");
      if (entry->has("set")) readEntrySets(*entry, g.sets);
    }
    // Relative to the study file; a configs/... path it does not hold follows the CLI's rule.
    const std::string beside = config::besideConfig(file, g.path);
    g.path = fs::exists(beside) ? beside : io::shippedIfMissing(g.path);
    if (!fs::exists(g.path)) g.path = beside;  // the loader then names the file it looked for
    if (g.name.empty()) g.name = fs::path(g.path).stem().string();
    if (!plainLabel(g.name)) root.fail("gaits", fmt::format("'{}' cannot name a folder", g.name));
    try {
      ocp::loadOcpConfig(g.path, g.sets);
    } catch (const config::ConfigError& e) {
      root.fail("gaits", e.what());
    }
    gaits.push_back(std::move(g));
  }
  return gaits;
}

/// A walk's or sweep's `options`, a robot read beside `file`: the config's path, not the reader's
/// label, which also names the --set overrides (a "/" in one moved the folder).
std::vector<ToolOption> readOptions(const YamlReader& r, const std::string& file) {
  std::vector<ToolOption> options;
  if (!r.has("options")) return options;
  const YamlReader map = r.map("options");
  map.allowOnly(kScenarioOptions);
  for (const std::string& name : map.keys()) {
    std::string value = map.string(name);
    if (name == "robot") value = config::besideConfig(file, value);
    options.push_back({name, value});
  }
  return options;
}

std::vector<std::string> controllers(const YamlReader& r) {
  return r.choices("controllers", sim::controllerNames());
}

WalkBlock readWalk(const YamlReader& r, const std::string& file) {
  r.allowOnly({"name", "options", "controllers", "plant"});
  WalkBlock w{r.string("name"), readOptions(r, file), controllers(r), "", {}};
  if (!plainLabel(w.name)) r.fail("name", "expected letters, digits and . _ + -");
  const YamlReader plant = r.map("plant");
  plant.allowOnly({"option", "values"});
  w.plant_option = plant.choice("option", {"mass-error", "length-error", "push", "uncertainty-case",
                                           "friction", "gain-scale"});
  w.plant_values = plant.yamlTexts("values");
  return w;
}

/// The `walks` list of a study or of a battery file.
std::vector<WalkBlock> readWalks(const YamlReader& r, const std::string& file) {
  std::vector<WalkBlock> walks;
  for (const YamlReader& walk : r.list("walks")) walks.push_back(readWalk(walk, file));
  return walks;
}

StabilityBlock readStability(const YamlReader& r, const std::string& file) {
  r.allowOnly({"options", "controllers", "sweeps"});
  return {readOptions(r, file), controllers(r), r.yamlTexts("sweeps")};
}

/// Each gait's points are written under its name: two gaits of one name (a file listed twice,
/// two entries of one file without `name`, a polynomial gait and a problem of one stem) would
/// share their folders, and the second would read the first's result as its own.
void refuseSharedFolders(const YamlReader& root, const StudyConfig& c) {
  std::vector<std::string> names;
  for (const PolynomialGait& poly : c.polynomial_gaits) names.push_back(gaitName(poly));
  for (const StudyGait& g : c.gaits) names.push_back(g.name);
  if (const auto twice = givenTwice(names))
    root.fail("gaits", fmt::format("two gaits are named '{}': their points would share one "
                                   "folder and one result; give each entry its own `name`",
                                   *twice));
}

}  // namespace

std::string gaitName(const PolynomialGait& poly) {
  return fs::path(poly.gait).stem().string();
}

StudyConfig loadStudyConfig(const std::string& path,
                            const std::vector<config::Override>& overrides) {
  const auto root = YamlReader::fromFile(path, overrides);
  root.allowOnly({"name", "description", "polynomial_gaits", "gaits", "set", "axes", "warm_start",
                  "walks", "walks_from", "stability"});
  StudyConfig c;
  c.name = root.string("name");
  root.stringOr("description", "");
  c.path = path;
  if (root.has("polynomial_gaits"))
    for (const YamlReader& poly : root.list("polynomial_gaits")) {
      poly.allowOnly({"gait", "robot"});
      c.polynomial_gaits.push_back({config::besideConfig(path, poly.string("gait")),
                                    config::besideConfig(path, poly.string("robot"))});
    }
  if (root.has("set")) readSets(root.map("set"), "", c.sets);
  if (root.has("gaits") || c.polynomial_gaits.empty()) c.gaits = readGaits(root, path, c.sets);
  refuseSharedFolders(root, c);
  if (root.has("axes"))
    for (const YamlReader& axis : root.list("axes")) c.axes.push_back(readAxis(axis, c.gaits));
  if (root.has("warm_start")) {
    const std::string warm = root.choice("warm_start", {"none", "previous", "previous_only"});
    c.warm_start = warm == "previous"        ? StudyConfig::WarmStart::kPrevious
                   : warm == "previous_only" ? StudyConfig::WarmStart::kPreviousOnly
                                             : StudyConfig::WarmStart::kNone;
  }
  if (root.has("walks_from")) {
    if (root.has("walks")) root.fail("walks_from", "give either walks or walks_from, not both");
    c.walks_file = config::besideConfig(path, root.string("walks_from"));
    const auto battery = YamlReader::fromFile(c.walks_file);
    battery.allowOnly({"walks"});
    c.walks = readWalks(battery, c.walks_file);
  } else if (root.has("walks")) {
    c.walks = readWalks(root, path);
  }
  if (root.has("stability"))
    for (const YamlReader& s : root.list("stability"))
      c.stability.push_back(readStability(s, path));
  return c;
}

}  // namespace gaitopt::study
