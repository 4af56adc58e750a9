#include "apps/cli_app.hpp"

#include <string>

#include "apps/commands/compare_command.hpp"
#include "apps/commands/export_urdf_command.hpp"
#include "apps/commands/impact_map_command.hpp"
#include "apps/commands/inspect_command.hpp"
#include "apps/commands/interpolate_command.hpp"
#include "apps/commands/optimize_command.hpp"
#include "apps/commands/poly_command.hpp"
#include "apps/option_checks.hpp"
#include "apps/study_commands/library_command.hpp"
#include "apps/study_commands/report_command.hpp"
#include "apps/study_commands/simulate_command.hpp"
#include "apps/study_commands/stability_command.hpp"
#include "apps/study_commands/study_command.hpp"
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
  registerStudyCommand(app);
  registerInterpolateCommand(app);
  registerReportCommand(app);
  requireFiniteNumbers(app);
}

}  // namespace gaitopt::apps
