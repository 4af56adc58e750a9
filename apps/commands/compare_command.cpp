#include "apps/commands/compare_command.hpp"

#include <filesystem>

#include <fmt/format.h>

#include "apps/command_runner.hpp"
#include "config/config_error.hpp"
#include "io/exit_code.hpp"
#include "io/output/output_folder.hpp"
#include "report/plot_script.hpp"

namespace gaitopt::apps {
namespace {

void requireResultFolder(const std::string& dir) {
  for (const char* file : {"summary.json", "trajectory.csv"})
    if (!std::filesystem::is_regular_file(dir + "/" + file))
      throw config::ConfigError(
          dir + "/" + file, "", 0,
          "missing: expected a gait result folder (gaitopt poly or optimize)");
}

}  // namespace

void runCompare(const CompareOptions& o) {
  const io::OutputFolder out(o.out_dir, o.dirs, "--out", "comparison");
  for (const std::string& dir : o.dirs) requireResultFolder(dir);
  // The report is the script's whole job: without matplotlib there is nothing to write.
  out.write([&](const std::string& dir) {
    std::vector<std::string> args = o.dirs;
    args.push_back(dir);
    // Its list of what it wrote names the staging folder (io/output/output_folder.hpp).
    const int status = report::plotScriptStatus("compare_gaits.py", args, io::Output::kErrors);
    if (status == report::kScriptInputError)  // a malformed folder; the script named the file
      throw io::CommandError(io::kExitInputError, "");
    if (status != 0) throw std::runtime_error("compare: plots/compare_gaits.py failed (see above)");
  });
  fmt::print("compare: wrote {}/comparison.md and the overlays\n", out.path());
}

void registerCompareCommand(CLI::App& app) {
  auto options = std::make_shared<CompareOptions>();
  CLI::App* cmd = app.add_subcommand(
      "compare", "Compare two to four gait result folders: table and overlaid plots");
  cmd->add_option("FOLDERS", options->dirs,
                  "Result folders, A first (e.g. results/poly_mu2004 results/poly_zmp_mu2004 "
                  "results/opt_mu2004)")
      ->required()
      ->expected(2, 4)
      ->option_text("A B [C [D]]");
  cmd->add_option("--out", options->out_dir, "Output folder (created)")
      ->required()
      ->option_text("DIR");
  cmd->footer("Exit codes: 0 ok, 2 a folder is not a gait result, 1 the report failed.");
  cmd->callback([options] { runSubcommand([&] { runCompare(*options); }); });
}

}  // namespace gaitopt::apps
