#include "apps/shipped_file.hpp"

#include <string>

#include "io/data_dir.hpp"

namespace gaitopt::apps {

CLI::Validator orShippedFile() {
  return CLI::Validator(
      [](std::string& path) {
        path = io::shippedIfMissing(path);
        return std::string();  // a missing file is the loader's error, which names it
      },
      "", "or shipped");
}

}  // namespace gaitopt::apps
