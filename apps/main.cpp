/// @file main.cpp
/// The `gaitopt` command-line tool. Each subcommand lives in its own <name>_command.cpp and is
/// registered here; exit codes are listed in command_runner.hpp.
#include <string>

#include <CLI/CLI.hpp>

#include "apps/command_runner.hpp"
#include "apps/compare_command.hpp"
#include "apps/impact_map_command.hpp"
#include "apps/inspect_command.hpp"
#include "apps/interpolate_command.hpp"
#include "apps/library_command.hpp"
#include "apps/optimize_command.hpp"
#include "apps/poly_command.hpp"
#include "apps/report_command.hpp"
#include "apps/simulate_command.hpp"
#include "apps/stability_command.hpp"

namespace {

std::string failureMessage(const CLI::App* app, const CLI::Error& e) {
  return "error: " + std::string(e.what()) + "\nRun '" + app->get_name() +
         " --help' for more information.\n";
}

void configure(CLI::App& app) {
  app.name("gaitopt");
  app.set_version_flag("--version", "gaitopt " GAITOPT_VERSION,
                       "Print the gaitopt version and exit");
  app.require_subcommand(1);
  app.failure_message(failureMessage);
  gaitopt::apps::registerInspectCommand(app);
  gaitopt::apps::registerPolyCommand(app);
  gaitopt::apps::registerOptimizeCommand(app);
  gaitopt::apps::registerImpactMapCommand(app);
  gaitopt::apps::registerSimulateCommand(app);
  gaitopt::apps::registerStabilityCommand(app);
  gaitopt::apps::registerCompareCommand(app);
  gaitopt::apps::registerLibraryCommand(app);
  gaitopt::apps::registerInterpolateCommand(app);
  gaitopt::apps::registerReportCommand(app);
}

/// Parses the command line and runs the chosen subcommand (from its callback).
int run(int argc, char** argv) {
  CLI::App app{"gaitopt: planar biped gait optimisation toolkit"};
  configure(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::RuntimeError& e) {
    return e.get_exit_code();  // a subcommand failed and has already printed its error
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);  // prints help, the version, or the usage error
    return code == 0 ? gaitopt::apps::kExitOk : gaitopt::apps::kExitInputError;
  }
  return gaitopt::apps::kExitOk;
}

}  // namespace

int main(int argc, char** argv) {
  int code = gaitopt::apps::kExitOk;
  const int status = gaitopt::apps::runReportingErrors([&] { code = run(argc, argv); });
  return status != gaitopt::apps::kExitOk ? status : code;
}
