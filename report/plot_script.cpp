#include "report/plot_script.hpp"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <system_error>

#include <fmt/format.h>

#include "io/data_dir.hpp"
#include "io/spawn.hpp"

namespace gaitopt::report {
namespace {

/// The shipped scripts (io/data_dir.hpp); GAITOPT_SCRIPTS overrides (the tests point it at a
/// missing folder to skip the pictures).
std::string scriptDir() {
  if (const char* env = std::getenv("GAITOPT_SCRIPTS")) return env;
  return io::dataFile("plots");
}

}  // namespace

int plotScriptStatus(const std::string& script, const std::vector<std::string>& args,
                     io::Output output) {
  std::fflush(stdout);  // keep our progress lines before the script's output
  const std::string python = "/usr/bin/python3";
  std::vector<std::string> argv = {python, scriptDir() + "/" + script};
  argv.insert(argv.end(), args.begin(), args.end());
  try {
    if (!std::filesystem::exists(python) ||
        io::runProgram({python, "-c", "import matplotlib"}, io::Output::kNone) != 0) {
      fmt::print(stderr,
                 "warning: no pictures: {} with matplotlib is missing "
                 "(apt-get install python3-matplotlib)\n",
                 python);
      return -1;
    }
    const int status = io::runProgram(argv, output);
    if (status != 0 && status != kScriptInputError)
      fmt::print(stderr, "warning: plotting failed: {} exited {}\n", script, status);
    return status;
  } catch (const std::system_error& e) {  // no process could be started (a process limit)
    fmt::print(stderr, "warning: no pictures: {}\n", e.what());
    return -1;
  }
}

bool runPlotScript(const std::string& script, const std::vector<std::string>& args,
                   io::Output output) {
  return plotScriptStatus(script, args, output) == 0;
}

bool holdsPictures(const std::string& dir) {
  std::error_code ec;
  for (const auto& entry : std::filesystem::directory_iterator(dir, ec))
    if (entry.path().extension() == ".png") return true;
  return false;
}

std::function<void(const std::string& dir)> gaitPictures(bool plots) {
  if (!plots) return {};
  return [](const std::string& dir) { runPlotScript("gait_plots.py", {dir}, io::Output::kErrors); };
}

}  // namespace gaitopt::report
