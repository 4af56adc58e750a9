#include "config/config_path.hpp"

#include <filesystem>

namespace gaitopt::config {

std::string besideConfig(const std::string& config_file, const std::string& path) {
  // operator/ keeps an absolute right-hand side as it is.
  return (std::filesystem::path(config_file).parent_path() / path).string();
}

}  // namespace gaitopt::config
