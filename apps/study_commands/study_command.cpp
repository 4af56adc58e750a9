#include "apps/study_commands/study_command.hpp"

#include <cstdio>
#include <filesystem>
#include <memory>

#include <fmt/format.h>

#include "apps/command_runner.hpp"
#include "apps/shipped_file.hpp"
#include "config/overrides.hpp"
#include "io/exit_code.hpp"
#include "io/output/output_folder.hpp"
#include "io/terminal_text.hpp"
#include "parallel/parallel_for.hpp"
#include "study/study_run.hpp"
#include "study/study_settings.hpp"

namespace gaitopt::apps {

void runStudyCommand(const StudyOptions& o) {
  const study::StudyConfig config =
      study::loadStudyConfig(o.config_path, config::parseOverrides(o.sets));
  const io::ResumableFolder folder(o.out_dir, study::studyInputs(config), study::kStudyFile);
  study::claimStudyFolder(config, o.sets, folder.path());
  study::StudyTools tools{std::filesystem::read_symlink("/proc/self/exe").string(), {}};
  if (!o.quiet)
    tools.progress = [](const std::string& what) {
      fmt::print("study: {}\n", what);
      std::fflush(stdout);  // a line per run also when stdout is a file
    };
  const study::StudyCounts n =
      study::runStudy(config, folder.path(), tools, parallel::resolveJobs(o.jobs));
  fmt::print("study: {}: {} of {} solves converged, {} walks, {} sweeps; wrote {}/solves.csv{}\n",
             config.name, n.converged, n.points, n.walks, n.sweeps, folder.path(),
             config.walks.empty() ? "" : ", walks.csv");
  if (n.unfinished > 0)
    throw io::CommandError(
        io::kExitFailure,
        fmt::format("{} ended without a result (killed, or stopped by the machine, e.g. a full "
                    "disk: see its .log under {}); the tables hold the rest. Run the study "
                    "again to redo {}",
                    io::counted(static_cast<std::size_t>(n.unfinished), "run"), folder.path(),
                    n.unfinished == 1 ? "it" : "them"));
}

void registerStudyCommand(CLI::App& app) {
  auto options = std::make_shared<StudyOptions>();
  CLI::App* cmd = app.add_subcommand(
      "study", "Solve configs over combinations of config values, walk and sweep each optimum");
  cmd->add_option("--config", options->config_path, "Study YAML (configs/studies/*.yaml)")
      ->required()
      ->transform(orShippedFile())
      ->option_text("FILE");
  cmd->add_option("--out", options->out_dir, "Study folder (created; reruns resume in it)")
      ->required()
      ->option_text("DIR");
  cmd->add_option("--set", options->sets, "Replace one value of the study config (repeatable)")
      ->option_text("KEY=VALUE");
  cmd->add_option("--jobs", options->jobs,
                  "Runs at once (default 1: the times a study measures are then undisturbed; 0: "
                  "every core)")
      ->check(CLI::Range(0, 1024));
  cmd->add_flag("--quiet", options->quiet, "No line per run");
  cmd->footer(
      "Each run is a gaitopt child process writing its own folder under DIR (runs/, walks/, "
      "stability/, its output in FOLDER.log); DIR/solves.csv, by_axis.md, walks.csv and "
      "stability.csv tabulate them. A failed solve is a row, not an error.");
  cmd->callback([options] { runSubcommand([&] { runStudyCommand(*options); }); });
}

}  // namespace gaitopt::apps
