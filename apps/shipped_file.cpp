#include "apps/shipped_file.hpp"

#include <string>

#include "io/data_dir.hpp"

namespace gaitopt::apps {

CLI::Validator orShippedFile() {
  return CLI::Validator(
      [](std::string& path) {
        if (path.rfind("configs/", 0) == 0)
          if (std::string found = io::localOrShipped(path); !found.empty()) path = found;
        return std::string();  // a missing file is the loader's error, which names it
      },
      "", "or shipped");
}

}  // namespace gaitopt::apps
