#include "io/settings_record.hpp"

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>

#include <fmt/format.h>

#include "config/config_error.hpp"
#include "io/output/checked_write.hpp"
#include "io/strict_json.hpp"
#include "io/terminal_text.hpp"

namespace gaitopt::io {
namespace {

std::string shown(const nlohmann::ordered_json& object, const std::string& key) {
  if (!object.contains(key)) return "(absent)";
  return printable(object[key].dump(-1, ' ', false, nlohmann::json::error_handler_t::replace));
}

/// Removes the times a run measured, at any depth.
void dropMeasuredTimes(nlohmann::ordered_json& j) {
  if (j.is_object()) {
    j.erase("wall_time_s");
    j.erase("callback_time_s");
  }
  if (j.is_structured())
    for (auto& child : j) dropMeasuredTimes(child);
}

}  // namespace

std::string textFingerprint(const std::string& text) {
  std::uint64_t hash = 14695981039346656037ULL;  // FNV-1a offset basis and prime
  for (const char c : text) hash = (hash ^ static_cast<unsigned char>(c)) * 1099511628211ULL;
  return fmt::format("{:016x}", hash);
}

std::string fileFingerprint(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw config::ConfigError(path, "", 0, "cannot read it");
  return textFingerprint({std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()});
}

std::string summaryFingerprint(const std::string& path) {
  nlohmann::ordered_json summary = readStrictJson(path);
  dropMeasuredTimes(summary);
  if (summary.is_object()) {
    summary.erase("config");
    summary.erase("kkt");
    summary.erase("solver");
  }
  return textFingerprint(summary.dump());
}

void claimSettings(const std::string& path, const nlohmann::ordered_json& settings) {
  if (!std::filesystem::exists(path)) {
    writeFileAtomically(path, settings.dump(2) + "\n");
    return;
  }
  const nlohmann::ordered_json recorded = readStrictJson(path);
  std::string differences, first;
  auto compare = [&](const std::string& key) {
    if (!recorded.is_object() || !recorded.contains(key) || !settings.contains(key) ||
        recorded[key] != settings[key]) {
      if (first.empty()) first = key;
      differences += fmt::format("\n  {}: folder {}, this run {}", key, shown(recorded, key),
                                 shown(settings, key));
    }
  };
  for (const auto& [key, value] : settings.items()) compare(key);
  if (recorded.is_object())
    for (const auto& [key, value] : recorded.items())
      if (!settings.contains(key)) compare(key);
  if (!differences.empty())
    throw config::ConfigError(path, first, 0,
                              "the folder holds rows made under other settings; rerun with "
                              "the same ones, or choose another --out:" +
                                  differences);
}

}  // namespace gaitopt::io
