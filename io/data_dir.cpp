#include "io/data_dir.hpp"

#include <cstdlib>
#include <filesystem>
#include <system_error>

namespace gaitopt::io {
namespace fs = std::filesystem;
namespace {

/// PREFIX/share/gaitopt of the running program PREFIX/bin/NAME, or "" when there is none.
fs::path besideExecutable() {
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (ec) return {};
  const fs::path share = exe.parent_path().parent_path() / "share" / "gaitopt";
  return fs::is_directory(share / "configs", ec) ? share : fs::path();
}

}  // namespace

std::string dataDir() {
  if (const char* env = std::getenv("GAITOPT_DATA_DIR"); env != nullptr && *env != '\0') return env;
  if (const fs::path share = besideExecutable(); !share.empty()) return share.string();
  std::error_code ec;
  if (fs::is_directory(fs::path(GAITOPT_SOURCE_DIR) / "configs", ec)) return GAITOPT_SOURCE_DIR;
  return GAITOPT_INSTALL_DATADIR;
}

std::string dataFile(const std::string& relative) {
  return (fs::path(dataDir()) / relative).string();
}

}  // namespace gaitopt::io
