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
  for (CLI::App* sub : app.get_subcommands({})) sub->callback({});  // parse only: no files
  try {
    app.parse(static_cast<int>(argv.size()), argv.data());
  } catch (const CLI::Error&) {  // usage errors, --help and --version
  }
  return 0;
}
