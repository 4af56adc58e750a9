/// @file main.cpp
/// The `gaitopt` command-line tool. Each subcommand lives in its own <name>_command.cpp and is
/// registered in cli_app.cpp; exit codes are listed in command_runner.hpp.
#include <cstdio>

#include <CLI/CLI.hpp>

#include "apps/cli_app.hpp"
#include "apps/command_runner.hpp"

namespace {

/// Parses the command line and runs the chosen subcommand (from its callback).
int run(int argc, char** argv) {
  CLI::App app{"gaitopt: planar biped gait optimisation toolkit"};
  gaitopt::apps::configureCli(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::RuntimeError& e) {
    return e.get_exit_code();  // a subcommand failed and has already printed its error
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);  // prints help, the version, or the usage error
    return code == 0 ? gaitopt::io::kExitOk : gaitopt::io::kExitInputError;
  }
  return gaitopt::io::kExitOk;
}

}  // namespace

int main(int argc, char** argv) {
  // A line on stdout is out as soon as it is printed, also into a file: a run interrupted or
  // killed overnight keeps its log up to its last line (a full buffer was lost with it).
  std::setvbuf(stdout, nullptr, _IOLBF, 0);
  int code = gaitopt::io::kExitOk;
  const int status = gaitopt::apps::runReportingErrors([&] { code = run(argc, argv); });
  return status != gaitopt::io::kExitOk ? status : code;
}
