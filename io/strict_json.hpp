#pragma once
/// @file strict_json.hpp
/// JSON read as strictly as the YAML readers: a key twice in one object is an error (nlohmann
/// would silently keep the last), so a hand-edited state or settings file cannot say two things.
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace gaitopt::io {

/// @throws config::ConfigError naming `path`: a syntax error (nlohmann's text) or a duplicate key.
[[noreturn]] void failJson(const std::string& path, const std::string& key,
                           const std::string& message);

/// Parses `text` (from `path`, named in errors) into Json (nlohmann::json or ordered_json).
/// @throws config::ConfigError on a syntax error or a duplicate key, naming the key.
template <class Json>
Json parseStrictJson(const std::string& text, const std::string& path) {
  std::vector<std::set<std::string>> keys;  // the keys seen in each open object
  std::string duplicate;
  const typename Json::parser_callback_t check = [&](int, typename Json::parse_event_t event,
                                                     Json& parsed) {
    using Event = typename Json::parse_event_t;
    if (event == Event::object_start) keys.emplace_back();
    if (event == Event::object_end && !keys.empty()) keys.pop_back();
    if (event == Event::key && !keys.empty() &&
        !keys.back().insert(parsed.template get<std::string>()).second && duplicate.empty())
      duplicate = parsed.template get<std::string>();
    return true;
  };
  Json j;
  try {
    j = Json::parse(text, check);
  } catch (const typename Json::exception& e) {
    failJson(path, "", e.what());
  }
  if (!duplicate.empty())
    failJson(path, duplicate, "the key appears twice in one object (which one is meant?)");
  return j;
}

/// Reads and parses `path` as parseStrictJson. @throws config::ConfigError (also when it cannot
/// be read).
nlohmann::ordered_json readStrictJson(const std::string& path);

}  // namespace gaitopt::io
