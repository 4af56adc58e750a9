#include "config/yaml_reader.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <map>
#include <utility>

#include <fmt/format.h>

#include "config/units.hpp"

namespace gaitopt::config {

NumberCheck positive(const std::string& unit) {
  return [unit](double v) { return v > 0 ? std::string() : "a positive number " + unit; };
}

NumberCheck nonNegative(const std::string& unit) {
  return [unit](double v) { return v >= 0 ? std::string() : "a number >= 0 " + unit; };
}

namespace {

/// "a number in [lo, hi] unit", without a space left over for no unit.
std::string rangeText(const char* what, double lo, double hi, const std::string& unit) {
  return fmt::format("{} in [{}, {}]{}{}", what, lo, hi, unit.empty() ? "" : " ", unit);
}

}  // namespace

NumberCheck inRange(double lo, double hi, const std::string& unit) {
  return [=](double v) {
    return (v >= lo && v <= hi) ? std::string() : rangeText("a number", lo, hi, unit);
  };
}

NumberCheck wholeInRange(double lo, double hi, const std::string& unit) {
  return [=](double v) {
    return (v >= lo && v <= hi && v == std::floor(v)) ? std::string()
                                                      : rangeText("a whole number", lo, hi, unit);
  };
}

NumberCheck inRange(const Quantity& q) {
  return [q](double v) { return rangeError(q, v).empty() ? std::string() : expectation(q); };
}

NumberCheck angleInRange(double lo, double hi) {
  return [=](double v) {
    if (v >= lo && v <= hi) return std::string();
    const std::string expected = fmt::format("an angle in [{:.4g}, {:.4g}] [rad]", lo, hi);
    const double as_radians = v * kDeg;
    if (as_radians < lo || as_radians > hi) return expected;
    return fmt::format("{} (degrees? {:g} deg is {:.4g} rad)", expected, v, as_radians);
  };
}

YamlReader YamlReader::fromFile(const std::string& path, const std::vector<Override>& overrides) {
  if (!std::filesystem::is_regular_file(path))
    throw ConfigError(path, "", 0, "file not found or not a regular file");
  YAML::Node root;
  try {
    root = YAML::LoadFile(path);
  } catch (const YAML::Exception& e) {
    throw ConfigError(path, "", e.mark.line + 1, "not valid YAML: " + e.msg);
  }
  if (!root.IsMap()) throw ConfigError(path, "", 0, "expected a YAML mapping at the top level");
  if (overrides.empty()) return YamlReader(path, root, "");
  applyOverrides(root, overrides);
  std::vector<std::string> texts;
  for (const Override& o : overrides) texts.push_back(o.option + " " + o.text());
  return YamlReader(fmt::format("{} ({})", path, fmt::join(texts, ", ")), root, "");
}

YamlReader::YamlReader(std::string file, YAML::Node node, std::string path)
    : file_(std::move(file)), node_(std::move(node)), path_(std::move(path)) {
  rejectDuplicateKeys();
}

void YamlReader::rejectDuplicateKeys() const {
  if (!node_.IsMap()) return;
  // yaml-cpp keeps both pairs of `{a: 1, a: 2}` and lookups return the first: a hand-edited
  // file would silently ignore the value the user changed last.
  std::map<std::string, int> first_line;
  for (const auto& kv : node_) {
    if (!kv.first.IsScalar()) continue;  // allowOnly() names keys that are not plain
    const auto [first, inserted] = first_line.emplace(kv.first.Scalar(), lineOf(kv.first));
    if (!inserted)
      throw ConfigError(file_, keyPath(kv.first.Scalar()), lineOf(kv.first),
                        fmt::format("duplicate key, first given at line {}; each key may "
                                    "appear once in a mapping",
                                    first->second));
  }
}

std::string YamlReader::keyPath(const std::string& key) const {
  return path_.empty() ? key : path_ + "." + key;
}

int YamlReader::lineOf(const YAML::Node& node) const {
  const auto mark = node.Mark();
  return mark.is_null() ? 0 : mark.line + 1;
}

void YamlReader::fail(const std::string& key, const std::string& message) const {
  const YAML::Node n = has(key) ? node_[key] : node_;
  throw ConfigError(file_, keyPath(key), lineOf(n), message);
}

bool YamlReader::has(const std::string& key) const {
  return node_.IsMap() && node_[key];
}

YAML::Node YamlReader::nonEmptyList(const std::string& key) const {
  const YAML::Node n = child(key);
  if (!n.IsSequence() || n.size() == 0) fail(key, "expected a non-empty list");
  return n;
}

YAML::Node YamlReader::child(const std::string& key) const {
  if (!has(key)) throw ConfigError(file_, keyPath(key), lineOf(node_), "missing required key");
  return node_[key];
}

namespace {

/// Strict decimal parse: the whole text must be one finite number.
bool parseFinite(const std::string& text, double& value) {
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), value);
  return ec == std::errc() && end == text.data() + text.size() && std::isfinite(value);
}

std::string describeNode(const YAML::Node& n) {
  if (n.IsScalar()) return "'" + n.Scalar() + "'";
  if (n.IsNull()) return "an empty value (null)";
  return n.IsMap() ? "a mapping" : "a sequence";
}

}  // namespace

double YamlReader::number(const std::string& key, const NumberCheck& check) const {
  const YAML::Node n = child(key);
  double value = 0;
  if (!n.IsScalar() || !parseFinite(n.Scalar(), value))
    fail(key, "expected a finite number, got " + describeNode(n));
  if (const std::string expected = check(value); !expected.empty())
    fail(key, fmt::format("expected {}, got {}", expected, n.Scalar()));
  return value;
}

double YamlReader::numberOr(const std::string& key, double fallback,
                            const NumberCheck& check) const {
  return has(key) ? number(key, check) : fallback;
}

std::optional<double> YamlReader::numberOrWord(const std::string& key, const std::string& word,
                                               const NumberCheck& check) const {
  const YAML::Node n = child(key);
  if (n.IsScalar() && n.Scalar() == word) return std::nullopt;
  double value = 0;
  if (!n.IsScalar() || !parseFinite(n.Scalar(), value))
    fail(key, fmt::format("expected a finite number or '{}', got {}", word, describeNode(n)));
  return number(key, check);
}

std::string YamlReader::choice(const std::string& key,
                               const std::vector<std::string>& allowed) const {
  const std::string value = string(key);
  if (std::find(allowed.begin(), allowed.end(), value) == allowed.end())
    fail(key, fmt::format("expected one of {}, got '{}'", fmt::join(allowed, ", "), value));
  return value;
}

bool YamlReader::boolean(const std::string& key) const {
  const YAML::Node n = child(key);
  const std::string text = n.IsScalar() ? n.Scalar() : std::string();
  if (text == "true") return true;
  if (text == "false") return false;
  fail(key, fmt::format("expected true or false, got '{}'", text));
}

bool YamlReader::booleanOr(const std::string& key, bool fallback) const {
  return has(key) ? boolean(key) : fallback;
}

std::string YamlReader::string(const std::string& key) const {
  const YAML::Node n = child(key);
  if (!n.IsScalar() || n.Scalar().empty()) fail(key, "expected a non-empty string");
  return n.Scalar();
}

std::string YamlReader::stringOr(const std::string& key, const std::string& fallback) const {
  return has(key) ? string(key) : fallback;
}

std::vector<double> YamlReader::numbers(const std::string& key, const NumberCheck& check) const {
  const YAML::Node n = child(key);
  if (n.IsScalar()) return {number(key, check)};
  if (!n.IsSequence() || n.size() == 0)
    fail(key, "expected a number or a non-empty list of numbers, got " + describeNode(n));
  std::vector<double> values;
  for (size_t i = 0; i < n.size(); ++i) {
    const std::string path = fmt::format("{}[{}]", keyPath(key), i);
    double value = 0;
    if (!n[i].IsScalar() || !parseFinite(n[i].Scalar(), value))
      throw ConfigError(file_, path, lineOf(n[i]),
                        "expected a finite number, got " + describeNode(n[i]));
    if (const std::string expected = check(value); !expected.empty())
      throw ConfigError(file_, path, lineOf(n[i]),
                        fmt::format("expected {}, got {}", expected, n[i].Scalar()));
    values.push_back(value);
  }
  return values;
}

std::vector<std::string> YamlReader::choices(const std::string& key,
                                             const std::vector<std::string>& allowed) const {
  const YAML::Node n = child(key);
  if (n.IsScalar()) return {choice(key, allowed)};
  if (!n.IsSequence() || n.size() == 0)
    fail(key, "expected a word or a non-empty list of words, got " + describeNode(n));
  std::vector<std::string> words;
  for (size_t i = 0; i < n.size(); ++i) {
    const std::string path = fmt::format("{}[{}]", keyPath(key), i);
    if (!n[i].IsScalar() ||
        std::find(allowed.begin(), allowed.end(), n[i].Scalar()) == allowed.end())
      throw ConfigError(
          file_, path, lineOf(n[i]),
          fmt::format("expected one of {}, got {}", fmt::join(allowed, ", "), describeNode(n[i])));
    words.push_back(n[i].Scalar());
  }
  return words;
}

bool YamlReader::isMap(const std::string& key) const {
  return has(key) && node_[key].IsMap();
}

YamlReader YamlReader::map(const std::string& key) const {
  const YAML::Node n = child(key);
  if (!n.IsMap()) fail(key, "expected a mapping of keys to values");
  return YamlReader(file_, n, keyPath(key));
}

std::vector<YamlReader> YamlReader::list(const std::string& key) const {
  const YAML::Node n = nonEmptyList(key);
  std::vector<YamlReader> items;
  for (size_t i = 0; i < n.size(); ++i) {
    const std::string path = fmt::format("{}[{}]", keyPath(key), i);
    if (!n[i].IsMap()) throw ConfigError(file_, path, lineOf(n[i]), "expected a mapping");
    items.emplace_back(file_, n[i], path);
  }
  return items;
}

namespace {

std::string flowText(const YAML::Node& node) {
  YAML::Emitter out;
  out << YAML::Flow << node;
  return out.c_str();
}

}  // namespace

std::vector<std::string> YamlReader::yamlTexts(const std::string& key) const {
  const YAML::Node n = nonEmptyList(key);
  std::vector<std::string> texts;
  for (const auto& item : n) texts.push_back(flowText(item));
  return texts;
}

std::string YamlReader::yamlText(const std::string& key) const {
  return flowText(child(key));
}

std::vector<std::optional<YamlReader>> YamlReader::maybeMaps(const std::string& key) const {
  const YAML::Node n = nonEmptyList(key);
  std::vector<std::optional<YamlReader>> items;
  for (size_t i = 0; i < n.size(); ++i)
    items.push_back(n[i].IsMap() ? std::optional<YamlReader>(std::in_place, file_, n[i],
                                                             fmt::format("{}[{}]", keyPath(key), i))
                                 : std::nullopt);
  return items;
}

std::vector<std::string> YamlReader::keys() const {
  std::vector<std::string> out;
  if (!node_.IsMap()) return out;
  for (const auto& kv : node_) {
    if (!kv.first.IsScalar())
      throw ConfigError(file_, path_, lineOf(kv.first),
                        "expected a plain key, got " + describeNode(kv.first) + " as a key");
    out.push_back(kv.first.Scalar());
  }
  return out;
}

void YamlReader::allowOnly(const std::vector<std::string>& allowed) const {
  keys();  // every key plain
  for (const auto& kv : node_) {
    const std::string key = kv.first.Scalar();
    if (std::find(allowed.begin(), allowed.end(), key) == allowed.end())
      throw ConfigError(file_, keyPath(key), lineOf(kv.first),
                        fmt::format("unknown key; allowed here: {}", fmt::join(allowed, ", ")));
  }
}

}  // namespace gaitopt::config
