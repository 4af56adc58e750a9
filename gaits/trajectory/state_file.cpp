#include "gaits/trajectory/state_file.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string_view>
#include <system_error>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "config/config_error.hpp"
#include "config/quantities.hpp"
#include "io/strict_json.hpp"

namespace gaitopt::gaits {
namespace {

using config::ConfigError;
using nlohmann::json;

struct VectorKey {
  config::Quantity quantity;  ///< its name is the key
  std::string_view what;
  bool required;
};

constexpr std::array<VectorKey, 3> kKeys{
    {{config::kLinkAngle, "absolute link angles [rad]", true},
     {config::kLinkRate, "absolute link rates [rad/s]", false},
     {config::kLinkAcceleration, "link accelerations [rad/s^2]", false}}};

/// A short rendering of a JSON value for error messages. Only scalars are dumped: dumping a
/// container recurses once per nesting level and overflows the stack on a deeply nested file.
std::string describe(const json& value) {
  if (value.is_array()) return fmt::format("an array of {} elements", value.size());
  if (value.is_object()) return fmt::format("an object with {} keys", value.size());
  if (value.is_null()) return "null";
  std::string text = value.dump(-1, ' ', false, json::error_handler_t::replace);
  if (text.size() > 40) text = text.substr(0, 37) + "...";
  return fmt::format("{} {}", value.type_name(), text);
}

json parseFile(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw ConfigError(path, "", 0, "state file not found or not a regular file");
  std::ifstream in(path);
  if (!in) throw ConfigError(path, "", 0, "cannot open the state file");
  std::ostringstream text;
  text << in.rdbuf();
  return io::parseStrictJson<json>(text.str(), path);
}

void checkKeys(const std::string& path, const json& doc) {
  if (!doc.is_object())
    throw ConfigError(path, "", 0,
                      fmt::format("expected a JSON object with keys theta (required), dtheta and "
                                  "ddtheta, got {}",
                                  describe(doc)));
  for (const auto& item : doc.items()) {
    const auto known = [&](const VectorKey& k) { return k.quantity.name == item.key(); };
    if (std::none_of(kKeys.begin(), kKeys.end(), known))
      throw ConfigError(path, item.key(), 0,
                        "unknown key; expected only theta, dtheta and ddtheta");
  }
}

VecD readVector(const std::string& path, const json& doc, const VectorKey& key, int n) {
  const std::string name(key.quantity.name);
  if (!doc.contains(name)) {
    if (key.required)
      throw ConfigError(path, name, 0, fmt::format("missing; expected {} {}", n, key.what));
    return VecD::Zero(n);
  }
  const json& value = doc.at(name);
  if (!value.is_array() || value.size() != static_cast<size_t>(n))
    throw ConfigError(path, name, 0,
                      fmt::format("expected an array of {} numbers ({}, one per link), got {}", n,
                                  key.what, describe(value)));
  VecD out(n);
  for (int i = 0; i < n; ++i) {
    const json& element = value.at(static_cast<size_t>(i));
    if (!element.is_number() || !std::isfinite(element.get<double>()))
      throw ConfigError(path, fmt::format("{}[{}]", name, i), 0,
                        fmt::format("expected a finite number, got {}", describe(element)));
    // A finite but huge value (1e308 rad/s) would overflow the energies to inf.
    out(i) = config::requireInRange(key.quantity, element.get<double>(), path,
                                    fmt::format("{}[{}]", name, i));
  }
  return out;
}

}  // namespace

ChainState standingState(const dynamics::Model& model) {
  const int n = model.nLinks();
  ChainState state{VecD::Zero(n), VecD::Zero(n), VecD::Zero(n)};
  for (int i = n - model.legLinks(); i < n; ++i) state.theta(i) = std::numbers::pi;
  return state;
}

ChainState loadState(const std::string& path, int n_links) {
  const json doc = parseFile(path);
  checkKeys(path, doc);
  return ChainState{readVector(path, doc, kKeys[0], n_links),
                    readVector(path, doc, kKeys[1], n_links),
                    readVector(path, doc, kKeys[2], n_links)};
}

}  // namespace gaitopt::gaits
