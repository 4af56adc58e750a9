// Fuzz target: the gaitopt command line (apps/cli_app.cpp) through CLI11 with every option
// check, the subcommands' work switched off. The input is the argument list, one argument per
// line. Passing: parsed, or a CLI11 usage error (what `gaitopt` turns into exit 2); any other
// exception, crash or sanitizer report is a finding.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "apps/cli_app.hpp"

namespace {

/// Thrown when every option is parsed and checked, before a subcommand's callback would run its
/// command (reading and writing files). The callbacks themselves must stay: each owns its
/// command's option storage (a shared_ptr), so replacing them freed the storage CLI11 then
/// parsed into (heap-use-after-free on the first seed).
struct Parsed {};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::vector<std::string> args{"gaitopt"};
  std::string current;
  for (size_t i = 0; i < size && args.size() < 64; ++i) {
    if (data[i] == '\n') {
      args.push_back(current);
      current.clear();
    } else {
      current += static_cast<char>(data[i]);
    }
  }
  if (!current.empty()) args.push_back(current);
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  CLI::App app;
  gaitopt::apps::configureCli(app);
  // The top-level app's parse-complete callback runs after all parsing and checking and before
  // the subcommands' callbacks (CLI::App::run_callback).
  app.parse_complete_callback([] { throw Parsed{}; });
  try {
    app.parse(static_cast<int>(argv.size()), argv.data());
  } catch (const CLI::Error&) {  // usage errors, --help and --version
  } catch (const Parsed&) {
  }
  return 0;
}
