#include "apps/cli_app.hpp"

#include <regex>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <fmt/ranges.h>

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

/// CLI11 checks what is required before it reports what it could not take, so a mistyped
/// command or required option ('optimise', '--confg') was reported only as missing the right one.
std::string withUnrecognised(const CLI::App* app, const CLI::Error& e) {
  const std::string what = io::printable(e.what());
  if (dynamic_cast<const CLI::RequiredError*>(&e) == nullptr) return what;
  const std::vector<CLI::App*> chosen = app->get_subcommands();
  const CLI::App* command = chosen.empty() ? app : chosen.front();
  const std::vector<std::string> words = command->remaining();
  if (words.empty()) return what;
  if (chosen.empty() && words.front().front() != '-') {
    std::string commands;
    for (const CLI::App* sub : app->get_subcommands({}))
      commands += (commands.empty() ? "" : ", ") + sub->get_name();
    return io::printable("unknown command '" + words.front() + "'; the commands: " + commands);
  }
  return io::printable(
             fmt::format("not an option of {}: {}", command->get_name(), fmt::join(words, " "))) +
         "; " + what;
}

/// CLI11's count of values ("FOLDERS: At Most 4 required but received 6") in plain words:
/// "FOLDERS: takes at most 4 values, got 6".
std::string plainCount(const CLI::Error& e, std::string what) {
  if (dynamic_cast<const CLI::ArgumentMismatch*>(&e) == nullptr) return what;
  static const std::regex count(R"((.*): At (Most|least) (\d+) required but received (\d+))");
  std::smatch m;
  if (!std::regex_match(what, m, count)) return what;
  return fmt::format("{}: takes at {} {} values, got {}", m[1].str(),
                     m[2] == "Most" ? "most" : "least", m[3].str(), m[4].str());
}

std::string failureMessage(const CLI::App* app, const CLI::Error& e) {
  return "error: " + plainCount(e, withUnrecognised(app, e)) + "\nRun '" + app->get_name() +
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
