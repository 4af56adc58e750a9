#include "config/config_error.hpp"

#include <utility>

#include <fmt/format.h>

namespace gaitopt::config {
namespace {

std::string describe(const std::string& file, const std::string& key, int line,
                     const std::string& message) {
  const std::string where = line > 0 ? fmt::format("{}:{}", file, line) : file;
  return key.empty() ? fmt::format("{}: {}", where, message)
                     : fmt::format("{}: key '{}': {}", where, key, message);
}

}  // namespace

ConfigError::ConfigError(std::string file, std::string key, int line, std::string message)
    : std::runtime_error(describe(file, key, line, message)),
      file_(std::move(file)),
      key_(std::move(key)),
      line_(line) {}

}  // namespace gaitopt::config
