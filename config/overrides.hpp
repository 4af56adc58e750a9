#pragma once
/// @file overrides.hpp
/// One config value given on the command line (`--set phases[0].segments=24`): the key path as
/// the readers name it in their messages (mappings joined by '.', list items by [i]) and the
/// value as YAML text. It replaces the value in the parsed document before the reader checks
/// it, so a value set this way is validated exactly as one in the file.
#include <string>
#include <vector>

#include <yaml-cpp/yaml.h>

namespace gaitopt::config {

struct Override {
  std::string key;               ///< e.g. "constraints.friction_margin", "phases[0].segments"
  std::string value;             ///< YAML text: a number, a word, a list "[0.1, 0.2]", ...
  std::string scope = "";        ///< the file a scoped --set named ("robot.", scopedOverrides)
  std::string option = "--set";  ///< how the caller named it, for messages ("set" in Python)
  /// As the user wrote it, for messages.
  std::string text() const { return scope + key + "=" + value; }
};

/// KEY=VALUE. @throws ConfigError naming `option` when there is no '=', no key or no value.
Override parseOverride(const std::string& text, const std::string& option = "--set");

/// parseOverride of each text, in order (a command's repeated --set, or `option`).
std::vector<Override> parseOverrides(const std::vector<std::string>& texts,
                                     const std::string& option = "--set");

/// The overrides of one of a command's several files: "robot.foot.heel=0.3" is key "foot.heel"
/// of the file of scope "robot". @throws ConfigError naming --set and the scopes when a text
/// starts with none of them.
std::vector<Override> scopedOverrides(const std::vector<std::string>& texts,
                                      const std::string& scope,
                                      const std::vector<std::string>& scopes);

/// Sets each override's value in the document `root`, creating missing mappings on the way
/// (the reader then refuses keys it does not know). The value `null` removes the key, so its
/// default applies (`--set variants=null`). @throws ConfigError naming --set and the
/// key when the path runs through a value that is not a mapping, or past a list's end.
void applyOverrides(YAML::Node& root, const std::vector<Override>& overrides);

/// The value at `key` (a path as Override::key spells it) in the document `root`, or a null
/// node when the document does not state it. @throws ConfigError naming --set for a malformed
/// path.
YAML::Node valueAt(const YAML::Node& root, const std::string& key);

}  // namespace gaitopt::config
