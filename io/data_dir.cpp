#include "io/data_dir.hpp"

#include <dlfcn.h>

#include <cstdlib>
#include <filesystem>
#include <system_error>

namespace gaitopt::io {
namespace fs = std::filesystem;
namespace {

/// PREFIX/share/gaitopt when `file` lies at most three folders below PREFIX (PREFIX/bin/gaitopt,
/// PREFIX/lib/python3/dist-packages/gaitopt.so), or "".
fs::path shareAbove(const fs::path& file) {
  std::error_code ec;
  fs::path dir = file.parent_path();
  for (int up = 0; up <= 3 && dir.has_relative_path(); ++up, dir = dir.parent_path())
    if (fs::is_directory(dir / "share" / "gaitopt" / "configs", ec))
      return dir / "share" / "gaitopt";
  return {};
}

/// The installed tree the running code came from: the program's (/proc/self/exe), or the
/// shared object's that holds this function (the Python module), or "".
fs::path installedShare() {
  std::error_code ec;
  if (const fs::path exe = fs::read_symlink("/proc/self/exe", ec); !ec)
    if (fs::path share = shareAbove(exe); !share.empty()) return share;
  Dl_info info{};
  if (::dladdr(reinterpret_cast<void*>(&installedShare), &info) != 0 && info.dli_fname != nullptr)
    return shareAbove(fs::absolute(info.dli_fname, ec));
  return {};
}

std::string& packageDataDir() {
  static std::string dir;
  return dir;
}

}  // namespace

void useInstalledDataDir(const std::string& dir) {
  packageDataDir() = dir;
}

std::string dataDir() {
  if (const char* env = std::getenv("GAITOPT_DATA_DIR"); env != nullptr && *env != '\0') return env;
  if (const fs::path share = installedShare(); !share.empty()) return share.string();
  if (!packageDataDir().empty()) return packageDataDir();
  std::error_code ec;
  if (fs::is_directory(fs::path(GAITOPT_SOURCE_DIR) / "configs", ec)) return GAITOPT_SOURCE_DIR;
  return GAITOPT_INSTALL_DATADIR;
}

std::string dataFile(const std::string& relative) {
  return (fs::path(dataDir()) / relative).string();
}

std::string shippedIfMissing(const std::string& path) {
  if (path.rfind("configs/", 0) != 0) return path;
  std::string found = localOrShipped(path);
  return found.empty() ? path : found;
}

std::string localOrShipped(const std::string& relative) {
  if (fs::exists(relative)) return relative;
  if (std::string shipped = dataFile(relative); fs::exists(shipped)) return shipped;
  return "";
}

}  // namespace gaitopt::io
