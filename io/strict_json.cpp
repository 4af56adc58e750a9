#include "io/strict_json.hpp"

#include <fstream>
#include <sstream>

#include "config/config_error.hpp"
#include "io/terminal_text.hpp"

namespace gaitopt::io {

void failJson(const std::string& path, const std::string& key, const std::string& message) {
  if (!key.empty()) throw config::ConfigError(path, printable(key), 0, message);
  // nlohmann messages start with "[json.exception.parse_error.101] "; keep what follows.
  const auto tag = message.find("] ");
  throw config::ConfigError(
      path, "", 0,
      "not valid JSON (" + printable(tag == std::string::npos ? message : message.substr(tag + 2)) +
          ")");
}

nlohmann::ordered_json readStrictJson(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw config::ConfigError(path, "", 0, "cannot read it");
  std::ostringstream text;
  text << in.rdbuf();
  return parseStrictJson<nlohmann::ordered_json>(text.str(), path);
}

}  // namespace gaitopt::io
