#include "apps/study_commands/library_command.hpp"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>

#include <fmt/format.h>

#include "apps/command_runner.hpp"
#include "apps/option_checks.hpp"
#include "apps/shipped_file.hpp"
#include "config/config_error.hpp"
#include "config/overrides.hpp"
#include "gaits/export/gait_summary.hpp"
#include "gaits/trajectory/grid_export.hpp"
#include "io/exit_code.hpp"
#include "io/output/output_folder.hpp"
#include "io/settings_record.hpp"
#include "library/library_folder.hpp"
#include "library/library_run.hpp"
#include "ocp/problem/ocp_config.hpp"
#include "parallel/mpi_executor.hpp"
#include "parallel/parallel_for.hpp"
#include "parallel/process_executor.hpp"
#include "report/plot_script.hpp"

namespace gaitopt::apps {
namespace {

std::string describeRow(const library::IndexRow& r) {
  if (!r.converged) return fmt::format("FAILED {} ({}) {}", r.status, r.start, r.message);
  return fmt::format("{} it, {:.2f} s, cost {:.5g}, CoT {:.4f} (poly {:.4f}), from {}",
                     r.iterations, r.solve_time_s, r.cost, r.cost_of_transport,
                     r.poly_cost_of_transport, r.start);
}

/// The points whose last row is an error (a full disk, a worker killed twice), and the first
/// one's message: a rerun without --retry-failed leaves them unsolved.
std::pair<int, std::string> earlierErrors(const library::LibrarySetup& setup,
                                          const library::LibraryIndex& index) {
  std::pair<int, std::string> errors{0, ""};
  for (int p = 0; p < setup.grid.size(); ++p)
    if (const auto row = index.row(setup.grid.point(p).name); row && row->status == "error")
      if (errors.first++ == 0) errors.second = row->point + ": " + row->message;
  return errors;
}

library::RunStats solveAll(const LibraryOptions& o, const library::LibrarySetup& setup,
                           library::LibraryIndex& index, parallel::Executor& executor) {
  library::ScheduleState state = library::previousState(setup, index, o.retry_failed);
  const auto todo = std::count(state.finished.begin(), state.finished.end(), false);
  if (!o.quiet)
    fmt::print("library: {} of {} points to solve on {} workers\n", todo, setup.grid.size(),
               executor.slots());
  return library::solveLibrary(setup, state, index, executor,
                               [&](const library::IndexRow& row, bool second_chance, int points) {
                                 if (!o.quiet)
                                   fmt::print("library: [{}/{}] {}{}: {}\n", points, todo,
                                              second_chance ? "second chance for " : "", row.point,
                                              describeRow(row));
                               });
}

void runScheduler(const LibraryOptions& o, const library::LibrarySetup& setup,
                  std::unique_ptr<parallel::Executor> executor) {
  std::vector<std::string> inputs = ocp::ocpInputs(setup.config.base);
  inputs.insert(inputs.end(), {o.config_path, setup.config.ocp_path});
  const io::ResumableFolder folder(setup.out_dir, inputs, library::kLibraryFile);
  std::filesystem::create_directories(setup.out_dir + "/points");
  library::claimLibraryFolder(setup);
  library::LibraryIndex index(setup.out_dir, setup.grid);
  const library::RunStats stats = solveAll(o, setup, index, *executor);
  executor.reset();  // stops the MPI ranks
  library::writeIndexJson(setup, index, stats);
  report::runPlotScript("library_plots.py", {setup.out_dir}, report::scriptOutput(o.quiet));
  fmt::print(
      "library: {} points solved, {} failed in {:.1f} s ({:.3f} points/s on {} workers); "
      "index in {}/index.csv\n",
      stats.points - stats.failed, stats.failed, stats.wall_time_s,
      stats.wall_time_s > 0 ? stats.points / stats.wall_time_s : 0.0, stats.workers, setup.out_dir);
  // A solver that did not converge is an outcome a library records; a point that could not be
  // set up or written (a full disk) is a failure of the run, also when an earlier run left it.
  if (stats.errors > 0)
    throw io::CommandError(io::kExitFailure,
                           fmt::format("{} point(s) ended in an error, not a solver outcome; the "
                                       "first: {}",
                                       stats.errors, stats.first_error));
  if (const auto [count, first] = earlierErrors(setup, index); count > 0)
    throw io::CommandError(io::kExitFailure,
                           fmt::format("{} point(s) ended in an error in an earlier run and are "
                                       "not solved (the first: {}); rerun with --retry-failed to "
                                       "redo them",
                                       count, first));
}

/// @throws config::ConfigError when two points of the grid would share a name.
library::Grid makeGrid(const library::LibraryConfig& config, const std::string& path) {
  double points = 1;
  for (const auto& axis : config.axes) points *= static_cast<double>(axis.size());
  for (const auto& axis : config.config_axes) points *= static_cast<double>(axis.values.size());
  // A point's grid entry, index row and schedule state: a few hundred bytes, rounded up.
  requireGridFits(points, 512, path + ": grid");
  try {
    return library::Grid(config.axes, config.config_axes);
  } catch (const std::invalid_argument& e) {
    throw config::ConfigError(path, "grid", 0, e.what());
  }
}

}  // namespace

void runLibrary(const LibraryOptions& o) {
  library::LibraryConfig config =
      library::loadLibraryConfig(o.config_path, config::parseOverrides(o.sets));
  library::Grid grid = makeGrid(config, o.config_path);
  // Every point would be solved and then refused at its export, and the folder claimed at a rate
  // a rerun must repeat: the shortest step is checked first.
  const auto& axes = grid.axes();
  gaits::requireExportRate(axes[library::kStepLength].front() / axes[library::kSpeed].back(),
                           o.rate_hz);
  // So is the longest step against the legs (exit 3, as optimize), before any point is solved.
  ocp::OcpConfig longest = config.base;
  longest.step_length = axes[library::kStepLength].back();
  ocp::requireReachable(ocp::problemModel(longest), longest, o.config_path);
  const library::LibrarySetup setup{
      std::move(config),
      std::move(grid),
      io::normaliseOutPath(o.out_dir, "--out"),
      {o.config_path, o.rate_hz, report::gaitPictures(o.plots), o.sets, {}}};
  const bool under_mpi = parallel::launchedByMpi();
  // No more worker processes than points.
  const int jobs =
      std::min(o.jobs > 0 ? o.jobs : (under_mpi ? 1 : parallel::resolveJobs(0)), setup.grid.size());
  // The workers are forked first, so they hold neither MPI's state nor its threads.
  auto local = std::make_unique<parallel::ProcessExecutor>(
      jobs,
      [&setup](const parallel::Job& job) {
        return library::toJson(library::solveLibraryPoint(setup, library::decodeJob(job.payload)))
            .dump();
      },
      [&setup](const parallel::Job& job, const std::string& why) {
        return library::toJson(
                   library::crashedPointRow(setup, library::decodeJob(job.payload), why))
            .dump();
      });
  if (!under_mpi) return runScheduler(o, setup, std::move(local));
  const parallel::MpiSession mpi;
  if (mpi.rank() > 0) return parallel::serveMpiJobs(mpi, *local);
  runScheduler(o, setup, parallel::makeMpiExecutor(mpi, std::move(local)));
}

void registerLibraryCommand(CLI::App& app) {
  auto o = std::make_shared<LibraryOptions>();
  CLI::App* cmd = app.add_subcommand(
      "library",
      "Solve a gait library: a grid of speed x step length x slope x any numeric config key");
  cmd->add_option("--config", o->config_path, "Library YAML (configs/library/*.yaml)")
      ->required()
      ->transform(orShippedFile())
      ->option_text("FILE");
  cmd->add_option("--out", o->out_dir, "Library folder (created; a rerun resumes it)")
      ->required()
      ->option_text("DIR");
  cmd->add_option("--jobs", o->jobs, "Worker processes (per MPI rank); 0: all cores (1 under MPI)")
      ->check(CLI::Range(0, 1024))
      ->default_val(0);
  cmd->add_flag("--retry-failed", o->retry_failed, "Solve again the points that failed before");
  cmd->add_option("--rate", o->rate_hz, "Sample rate of each point's trajectory.csv [Hz]")
      ->check(quantityRange(config::kSampleRate))
      ->default_val(250);
  cmd->add_flag("--plots", o->plots, "Pictures of every point (slow; the chart is always drawn)");
  cmd->add_option("--set", o->sets,
                  "Replace one value of the library config, e.g. --set grid.speed=[0.4,0.6] "
                  "(repeatable; checked as the file is, recorded in each point's summary.json)")
      ->option_text("KEY=VALUE");
  cmd->add_flag("--quiet", o->quiet, "No line per point");
  cmd->footer(
      "Under MPI (mpirun -np N gaitopt library ...), rank 0 schedules and every rank solves; "
      "the folder must be on a file system all ranks share. A failed point is listed in "
      "index.csv with its status and does not stop the library. Exit codes: 0 done (failed "
      "points included), 2 bad input, 1 other failure.");
  cmd->callback([o] { runSubcommand([&] { runLibrary(*o); }); });
}

}  // namespace gaitopt::apps
