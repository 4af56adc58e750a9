#include "apps/shipped_file.hpp"

#include <filesystem>
#include <string>

#include "io/data_dir.hpp"

namespace gaitopt::apps {

CLI::Validator orShippedFile() {
  return CLI::Validator(
      [](std::string& path) {
        namespace fs = std::filesystem;
        if (path.rfind("configs/", 0) != 0 || fs::exists(path)) return std::string();
        if (const std::string shipped = io::dataFile(path); fs::exists(shipped)) path = shipped;
        return std::string();  // a missing file is the loader's error, which names it
      },
      "", "or shipped");
}

}  // namespace gaitopt::apps
