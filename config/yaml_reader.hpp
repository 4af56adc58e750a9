#pragma once
/// @file yaml_reader.hpp
/// Strict typed access to one YAML mapping: every read names its key path, every failure throws a
/// ConfigError with file, key, line, the value found and what was expected; unknown and
/// duplicate keys are errors (a typo must never fall back to a silent default).
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

#include "config/config_error.hpp"
#include "config/overrides.hpp"
#include "config/quantities.hpp"

namespace gaitopt::config {

/// A range check on a number: returns an empty string when the value is acceptable, otherwise
/// the expectation to print (e.g. "a positive number [kg]").
using NumberCheck = std::function<std::string(double)>;

NumberCheck positive(const std::string& unit);
NumberCheck nonNegative(const std::string& unit);
NumberCheck inRange(double lo, double hi, const std::string& unit);
/// A count in [lo, hi] (segments, iterations, steps): a fraction is refused rather than cut.
NumberCheck wholeInRange(double lo, double hi, const std::string& unit);
/// The range of a quantity a user also sets elsewhere (a sweep axis, an option), in its words.
NumberCheck inRange(const Quantity& q);
/// An angle in [lo, hi] radians; a value outside that is in range once read as degrees gets
/// a hint to convert ("30 deg is 0.5236 rad"), the usual slip in a hand-edited file.
NumberCheck angleInRange(double lo, double hi);

class YamlReader {
 public:
  /// Parses a file, with `overrides` (--set) put in place of the file's values; every error
  /// about the document then names the file and the overrides. @throws ConfigError when it is
  /// missing or not valid YAML mapping, or an override does not fit it.
  static YamlReader fromFile(const std::string& path, const std::vector<Override>& overrides = {});
  /// Wraps a parsed node; `path` is the key path of the node ("" for the document root).
  /// @throws ConfigError when the node is a mapping with a key given twice (both lines named).
  YamlReader(std::string file, YAML::Node node, std::string path);

  double number(const std::string& key, const NumberCheck& check) const;
  double numberOr(const std::string& key, double fallback, const NumberCheck& check) const;
  /// A number, or std::nullopt when the value is the word `word` (e.g. "optimize").
  std::optional<double> numberOrWord(const std::string& key, const std::string& word,
                                     const NumberCheck& check) const;
  /// A string that must be one of `allowed`.
  std::string choice(const std::string& key, const std::vector<std::string>& allowed) const;
  bool boolean(const std::string& key) const;
  bool booleanOr(const std::string& key, bool fallback) const;
  std::string string(const std::string& key) const;
  std::string stringOr(const std::string& key, const std::string& fallback) const;
  /// One number or a non-empty list of numbers, each checked (e.g. `speed: [0.4, 0.6]`).
  std::vector<double> numbers(const std::string& key, const NumberCheck& check) const;
  /// One word or a non-empty list of words, each one of `allowed` (e.g. `order: [margins, cost]`).
  std::vector<std::string> choices(const std::string& key,
                                   const std::vector<std::string>& allowed) const;
  /// Each item of the non-empty list under `key` as one line of YAML text (a number, a word, a
  /// flow list or mapping), to be set elsewhere as written (a study axis' `--set` values).
  std::vector<std::string> yamlTexts(const std::string& key) const;
  /// The value under `key` as one line of YAML text.
  std::string yamlText(const std::string& key) const;
  /// The mapping under `key`.
  YamlReader map(const std::string& key) const;
  /// Whether the value under `key` is a mapping (e.g. a range `{from, to, count}`).
  bool isMap(const std::string& key) const;
  bool has(const std::string& key) const;
  /// Elements of the non-empty sequence under `key`, each a mapping.
  std::vector<YamlReader> list(const std::string& key) const;
  /// For each element of the non-empty sequence under `key`, its reader when it is a mapping
  /// (a list whose items are either a plain value or a mapping spelling it out).
  std::vector<std::optional<YamlReader>> maybeMaps(const std::string& key) const;
  /// The mapping's keys in the file's order (empty when it is not a mapping).
  /// @throws ConfigError naming a key that is not plain text.
  std::vector<std::string> keys() const;
  /// @throws ConfigError naming the first key not in `allowed`.
  void allowOnly(const std::vector<std::string>& allowed) const;

  const std::string& file() const { return file_; }
  [[noreturn]] void fail(const std::string& key, const std::string& message) const;

 private:
  YAML::Node child(const std::string& key) const;
  /// The sequence under `key`. @throws ConfigError unless it is one with at least one item.
  YAML::Node nonEmptyList(const std::string& key) const;
  std::string keyPath(const std::string& key) const;
  int lineOf(const YAML::Node& node) const;
  void rejectDuplicateKeys() const;

  std::string file_;
  YAML::Node node_;
  std::string path_;
};

}  // namespace gaitopt::config
