#include "apps/result_folder.hpp"

#include <unistd.h>

#include <filesystem>

namespace gaitopt::apps {

void writeResultFolder(const std::string& dir,
                       const std::function<void(const std::string&)>& write) {
  namespace fs = std::filesystem;
  const fs::path target = fs::path(dir).lexically_normal();
  // Appended piece by piece: "literal" + std::string trips a GCC 12 -Wrestrict false alarm.
  const std::string pid = std::to_string(::getpid());
  fs::path staging = target, old = target;
  staging += ".tmp-";
  staging += pid;
  old += ".old-";
  old += pid;
  if (target.has_parent_path()) fs::create_directories(target.parent_path());
  fs::remove_all(staging);
  fs::create_directories(staging);
  try {
    write(staging.string());
  } catch (...) {
    fs::remove_all(staging);
    throw;
  }
  // Two renames: the old result stays whole until the new one is in place.
  if (fs::exists(target)) fs::rename(target, old);
  fs::rename(staging, target);
  fs::remove_all(old);
}

}  // namespace gaitopt::apps
