#include "config/overrides.hpp"

#include <algorithm>
#include <charconv>
#include <utility>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "config/config_error.hpp"

namespace gaitopt::config {
namespace {

/// One step of a key path: a mapping key, or a list index.
struct Step {
  std::string key;
  int index = -1;         ///< >= 0: a list item
  std::size_t start = 0;  ///< where the step begins in the key path
};

[[noreturn]] void refuse(const Override& o, const std::string& why) {
  throw ConfigError(o.option, o.key, 0, fmt::format("'{}': {}", o.text(), why));
}

/// "a.b[2].c" as a, b, [2], c.
std::vector<Step> stepsOf(const Override& o) {
  std::vector<Step> steps;
  std::size_t at = 0;
  while (at <= o.key.size()) {
    const std::size_t end = std::min(o.key.find('.', at), o.key.size());
    const std::string part = o.key.substr(at, end - at);
    const std::size_t bracket = part.find('[');
    if (part.empty() || bracket == 0) refuse(o, "expected a key path such as constraints.zmp");
    steps.push_back({part.substr(0, bracket), -1, at});
    for (std::size_t b = bracket; b != std::string::npos; b = part.find('[', b + 1)) {
      const std::size_t close = part.find(']', b);
      int index = -1;
      const auto [ptr, ec] = std::from_chars(part.data() + b + 1, part.data() + close, index);
      if (close == std::string::npos || ec != std::errc() || ptr != part.data() + close ||
          index < 0)
        refuse(o, "expected a list index such as phases[0]");
      steps.push_back({"", index});
    }
    at = end + 1;
  }
  return steps;
}

/// The child of `node` at `step` (a mapping is created where the path names a missing key).
YAML::Node childOf(YAML::Node& node, const Step& step, const Override& o) {
  if (step.index >= 0) {
    if (!node.IsSequence())
      refuse(o,
             fmt::format("there is no list item [{}] there: the value is not a list", step.index));
    if (static_cast<std::size_t>(step.index) >= node.size())
      refuse(o, fmt::format("there is no list item [{}] there: {}", step.index,
                            node.size() == 0 ? std::string("the list is empty")
                                             : fmt::format("the list has {} item(s), [0] to [{}]",
                                                           node.size(), node.size() - 1)));
    return node[step.index];
  }
  if (!node.IsMap() && !node.IsNull()) refuse(o, "the path runs through a value, not a mapping");
  if (!node[step.key]) node[step.key] = YAML::Node(YAML::NodeType::Map);
  return node[step.key];
}

/// Whether the rest of the path from step `i` is one key of the mapping `node`: a mapping whose
/// keys are themselves paths (a library's grid: `phases[0].segments: [24, 30]`) holds that key
/// already, or does not hold the list the path would index into.
bool literalKeyAt(const YAML::Node& node, const std::vector<Step>& steps, std::size_t i,
                  const Override& o) {
  if (steps[i].index >= 0 || !node.IsMap()) return false;
  const std::string rest = o.key.substr(steps[i].start);
  if (node[rest]) return true;
  return steps[i + 1].index >= 0 && !node[steps[i].key];
}

}  // namespace

Override parseOverride(const std::string& text, const std::string& option) {
  const std::size_t eq = text.find('=');
  if (eq == std::string::npos || eq == 0 || eq + 1 == text.size())
    throw ConfigError(option, text, 0,
                      "expected KEY=VALUE, e.g. " + option + " constraints.friction_margin=0.2");
  return {text.substr(0, eq), text.substr(eq + 1), "", option};
}

std::vector<Override> parseOverrides(const std::vector<std::string>& texts,
                                     const std::string& option) {
  std::vector<Override> overrides;
  for (const std::string& text : texts) overrides.push_back(parseOverride(text, option));
  return overrides;
}

std::vector<Override> scopedOverrides(const std::vector<std::string>& texts,
                                      const std::string& scope,
                                      const std::vector<std::string>& scopes) {
  std::vector<Override> overrides;
  for (const Override& o : parseOverrides(texts)) {
    const std::size_t dot = o.key.find('.');
    const std::string prefix = o.key.substr(0, dot);
    if (dot == std::string::npos || std::find(scopes.begin(), scopes.end(), prefix) == scopes.end())
      throw ConfigError(o.option, o.key, 0,
                        fmt::format("'{}': the key starts with the file it sets: {}.KEY", o.text(),
                                    fmt::join(scopes, ".KEY or ")));
    if (prefix == scope)
      overrides.push_back({o.key.substr(dot + 1), o.value, prefix + ".", o.option});
  }
  return overrides;
}

void applyOverrides(YAML::Node& root, const std::vector<Override>& overrides) {
  for (const Override& o : overrides) {
    YAML::Node value;
    try {
      value = YAML::Load(o.value);
    } catch (const YAML::Exception& e) {
      refuse(o, "the value is not valid YAML: " + e.msg);
    }
    const std::vector<Step> steps = stepsOf(o);
    YAML::Node node = root;
    std::size_t i = 0;
    for (; i + 1 < steps.size(); ++i) {
      if (literalKeyAt(node, steps, i, o)) break;
      node.reset(childOf(node, steps[i], o));
    }
    if (i + 1 < steps.size()) {  // a key that is itself a path, set or removed whole
      const std::string rest = o.key.substr(steps[i].start);
      if (value.IsNull())
        node.remove(rest);
      else
        node[rest] = value;
      continue;
    }
    // `null` deletes the key, so the reader's default (or absence) applies, as deleting the
    // line would; a leaf that is a mapping or list in the file is replaced whole.
    if (value.IsNull() && steps.back().index < 0 && (node.IsMap() || node.IsNull()))
      node.remove(steps.back().key);
    else
      childOf(node, steps.back(), o) = value;
  }
}

YAML::Node valueAt(const YAML::Node& root, const std::string& key) {
  YAML::Node node = YAML::Clone(root);
  for (const Step& step : stepsOf({key, ""})) {
    const bool present =
        step.index >= 0 ? node.IsSequence() && static_cast<std::size_t>(step.index) < node.size()
                        : node.IsMap() && node[step.key];
    if (!present) return YAML::Node(YAML::NodeType::Null);
    node.reset(step.index >= 0 ? node[step.index] : node[step.key]);
  }
  return node;
}

}  // namespace gaitopt::config
