#include "apps/cli_app.hpp"

#include <string>

#include "apps/compare_command.hpp"
#include "apps/export_urdf_command.hpp"
#include "apps/impact_map_command.hpp"
#include "apps/inspect_command.hpp"
#include "apps/interpolate_command.hpp"
#include "apps/library_command.hpp"
#include "apps/optimize_command.hpp"
#include "apps/option_checks.hpp"
#include "apps/poly_command.hpp"
#include "apps/report_command.hpp"
#include "apps/simulate_command.hpp"
#include "apps/stability_command.hpp"
#include "io/terminal_text.hpp"

namespace gaitopt::apps {
namespace {

std::string failureMessage(const CLI::App* app, const CLI::Error& e) {
  return "error: " + io::printable(e.what()) + "\nRun '" + app->get_name() +
         " --help' for more information.\n";
}

}  // namespace

void configureCli(CLI::App& app) {
  app.name("gaitopt");
  app.set_version_flag("--version", "gaitopt " GAITOPT_VERSION,
                       "Print the gaitopt version and exit");
  app.require_subcommand(1);
  app.failure_message(failureMessage);
  registerInspectCommand(app);
  registerExportUrdfCommand(app);
  registerPolyCommand(app);
  registerOptimizeCommand(app);
  registerImpactMapCommand(app);
  registerSimulateCommand(app);
  registerStabilityCommand(app);
  registerCompareCommand(app);
  registerLibraryCommand(app);
  registerInterpolateCommand(app);
  registerReportCommand(app);
  requireFiniteNumbers(app);
}

}  // namespace gaitopt::apps
