#include "apps/plotting.hpp"

#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include <fmt/format.h>

namespace gaitopt::apps {
namespace {

/// Scripts live in the source tree; GAITOPT_SCRIPTS overrides (an installed copy).
std::string scriptDir() {
  if (const char* env = std::getenv("GAITOPT_SCRIPTS")) return env;
  return GAITOPT_SOURCE_DIR "/scripts/plots";
}

}  // namespace

bool runPlotScript(const std::string& script, const std::string& args) {
  std::fflush(stdout);  // keep our progress lines before the script's output
  const std::string python = "/usr/bin/python3";
  if (!std::filesystem::exists(python) ||
      std::system(fmt::format("{} -c 'import matplotlib' 2>/dev/null", python).c_str()) != 0) {
    fmt::print(stderr,
               "warning: no pictures: {} with matplotlib is missing "
               "(apt-get install python3-matplotlib)\n",
               python);
    return false;
  }
  const std::string cmd = fmt::format("{} '{}/{}' {}", python, scriptDir(), script, args);
  if (std::system(cmd.c_str()) != 0) {
    fmt::print(stderr, "warning: plotting failed: {}\n", cmd);
    return false;
  }
  return true;
}

}  // namespace gaitopt::apps
