#include "apps/library_command.hpp"

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>

#include <fmt/format.h>

#include "apps/command_runner.hpp"
#include "apps/library_point.hpp"
#include "apps/option_checks.hpp"
#include "apps/plotting.hpp"
#include "config/config_error.hpp"
#include "gaits/gait_summary.hpp"
#include "io/output_folder.hpp"
#include "io/settings_record.hpp"
#include "parallel/mpi_executor.hpp"
#include "parallel/parallel_for.hpp"
#include "parallel/process_executor.hpp"

namespace gaitopt::apps {
namespace {

/// The base OCP file relative to the library folder, so the folder and the configs can move
/// together (a clone of the repository elsewhere).
std::string ocpPathFromFolder(const LibrarySetup& s) {
  namespace fs = std::filesystem;
  return fs::relative(fs::absolute(s.config.ocp_path), fs::absolute(s.out_dir)).string();
}

/// library.json: what the folder is a library of. A rerun with another grid or base problem
/// would mix gaits of two libraries in one index, so it is refused.
void claimFolder(const LibrarySetup& s) {
  nlohmann::ordered_json axes;
  for (int a = 0; a < 3; ++a) axes[library::kAxisNames[a]] = s.grid.axes()[a];
  const nlohmann::ordered_json claim = {
      {"name", s.config.name}, {"ocp", ocpPathFromFolder(s)}, {"axes", axes}};
  io::claimSettings(s.out_dir + "/library.json", claim);
}

/// Points finished in earlier runs: solved ones whose folder is still there, and failed ones
/// unless they are to be retried.
library::ScheduleState previousState(const LibrarySetup& s, const LibraryIndex& index,
                                     bool retry_failed) {
  const auto n = static_cast<std::size_t>(s.grid.size());
  library::ScheduleState state{std::vector<bool>(n, false), std::vector<bool>(n, false)};
  for (int p = 0; p < s.grid.size(); ++p) {
    const auto row = index.row(s.grid.point(p).name);
    if (!row) continue;
    const bool solved =
        row->converged && std::filesystem::exists(s.pointDir(p) + "/trajectory.csv");
    state.solved[static_cast<std::size_t>(p)] = solved;
    state.finished[static_cast<std::size_t>(p)] = solved || (!row->converged && !retry_failed);
  }
  return state;
}

std::string describeRow(const IndexRow& r) {
  if (!r.converged) return fmt::format("FAILED {} ({}) {}", r.status, r.start, r.message);
  return fmt::format("{} it, {:.2f} s, cost {:.5g}, CoT {:.4f} (poly {:.4f}), from {}",
                     r.iterations, r.solve_time_s, r.cost, r.cost_of_transport,
                     r.poly_cost_of_transport, r.start);
}

/// What a run did: points finished in it (each once, second chances included), of those failed
/// at the end, and solves (second chances counted apart).
struct RunStats {
  int points = 0, failed = 0, solves = 0, workers = 0;
  double wall_time_s = 0;
};

RunStats solveAll(const LibraryOptions& o, const LibrarySetup& setup, LibraryIndex& index,
                  parallel::Executor& executor) {
  library::ScheduleState state = previousState(setup, index, o.retry_failed);
  const auto todo = std::count(state.finished.begin(), state.finished.end(), false);
  RunStats stats{0, 0, 0, executor.slots(), 0};
  const library::ScheduleState before = state;
  if (!o.quiet)
    fmt::print("library: {} of {} points to solve on {} workers\n", todo, setup.grid.size(),
               executor.slots());
  const auto start = std::chrono::steady_clock::now();
  const int root = setup.grid.nearest(library::basePoint(setup.config.base));
  library::runSchedule(setup.grid, root, state, executor,
                       [&](const library::PointJob&, const parallel::JobResult& r) {
                         const IndexRow row = indexRowFromJson(nlohmann::json::parse(r.payload));
                         index.append(row);
                         const bool again = state.finished[static_cast<std::size_t>(r.id)];
                         stats.points += again ? 0 : 1;
                         ++stats.solves;
                         if (!o.quiet)
                           fmt::print("library: [{}/{}] {}{}: {}\n", stats.points, todo,
                                      again ? "second chance for " : "", row.point,
                                      describeRow(row));
                         return row.converged;
                       });
  for (std::size_t p = 0; p < state.solved.size(); ++p)
    stats.failed += !before.finished[p] && !state.solved[p] ? 1 : 0;
  stats.wall_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return stats;
}

/// The last run that solved something: a rerun with nothing left to do keeps the figures of
/// the run that built the library.
nlohmann::ordered_json lastRun(const std::string& path, const RunStats& s) {
  if (s.points == 0 && std::filesystem::exists(path)) {
    std::ifstream in(path);
    const auto previous = nlohmann::ordered_json::parse(in, nullptr, false);
    if (!previous.is_discarded() && previous.contains("last_run")) return previous["last_run"];
  }
  return {{"points", s.points},
          {"failed", s.failed},
          {"solves", s.solves},
          {"workers", s.workers},
          {"wall_time_s", s.wall_time_s},
          {"points_per_second", s.wall_time_s > 0 ? s.points / s.wall_time_s : 0.0}};
}

void writeIndexJson(const LibrarySetup& setup, const LibraryIndex& index, const RunStats& s) {
  const std::string path = setup.out_dir + "/index.json";
  auto json = index.json(setup.grid);
  json["last_run"] = lastRun(path, s);
  gaits::writeJsonFile(json, path);
}

void runScheduler(const LibraryOptions& o, const LibrarySetup& setup,
                  std::unique_ptr<parallel::Executor> executor) {
  const io::ResumableFolder folder(setup.out_dir, {o.config_path, setup.config.ocp_path});
  std::filesystem::create_directories(setup.out_dir + "/points");
  claimFolder(setup);
  LibraryIndex index(setup.out_dir);
  const RunStats stats = solveAll(o, setup, index, *executor);
  executor.reset();  // stops the MPI ranks
  writeIndexJson(setup, index, stats);
  runPlotScript("library_plots.py", {setup.out_dir});
  fmt::print(
      "library: {} points solved, {} failed in {:.1f} s ({:.3f} points/s on {} workers); "
      "index in {}/index.csv\n",
      stats.points - stats.failed, stats.failed, stats.wall_time_s,
      stats.wall_time_s > 0 ? stats.points / stats.wall_time_s : 0.0, stats.workers, setup.out_dir);
}

/// @throws config::ConfigError when two points of the grid would share a name.
library::Grid makeGrid(const library::LibraryConfig& config, const std::string& path) {
  double points = 1;
  for (const auto& axis : config.axes) points *= static_cast<double>(axis.size());
  // A point's grid entry, index row and schedule state: a few hundred bytes, rounded up.
  requireGridFits(points, 512, path + ": grid");
  try {
    return library::Grid(config.axes);
  } catch (const std::invalid_argument& e) {
    throw config::ConfigError(path, "grid", 0, e.what());
  }
}

}  // namespace

void runLibrary(const LibraryOptions& o) {
  library::LibraryConfig config = library::loadLibraryConfig(o.config_path);
  library::Grid grid = makeGrid(config, o.config_path);
  const LibrarySetup setup{std::move(config),
                           std::move(grid),
                           io::normaliseOutPath(o.out_dir, "--out"),
                           {o.config_path, o.rate_hz, gaitPictures(o.plots)}};
  const bool under_mpi = parallel::launchedByMpi();
  // No more worker processes than points.
  const int jobs =
      std::min(o.jobs > 0 ? o.jobs : (under_mpi ? 1 : parallel::resolveJobs(0)), setup.grid.size());
  // The workers are forked first, so they hold neither MPI's state nor its threads.
  auto local = std::make_unique<parallel::ProcessExecutor>(
      jobs,
      [&setup](const parallel::Job& job) {
        return toJson(solveLibraryPoint(setup, library::decodeJob(job.payload))).dump();
      },
      [&setup](const parallel::Job& job, const std::string& why) {
        return toJson(crashedPointRow(setup, library::decodeJob(job.payload), why)).dump();
      });
  if (!under_mpi) return runScheduler(o, setup, std::move(local));
  const parallel::MpiSession mpi;
  if (mpi.rank() > 0) return parallel::serveMpiJobs(mpi, *local);
  runScheduler(o, setup, parallel::makeMpiExecutor(mpi, std::move(local)));
}

void registerLibraryCommand(CLI::App& app) {
  auto o = std::make_shared<LibraryOptions>();
  CLI::App* cmd =
      app.add_subcommand("library", "Solve a gait library: a grid of speed x step length x slope");
  cmd->add_option("--config", o->config_path, "Library YAML (configs/library/*.yaml)")
      ->required()
      ->option_text("FILE");
  cmd->add_option("--out", o->out_dir, "Library folder (created; a rerun resumes it)")
      ->required()
      ->option_text("DIR");
  cmd->add_option("--jobs", o->jobs, "Worker threads (per MPI rank); 0: all cores (1 under MPI)")
      ->check(CLI::Range(0, 1024))
      ->default_val(0);
  cmd->add_flag("--retry-failed", o->retry_failed, "Solve again the points that failed before");
  cmd->add_option("--rate", o->rate_hz, "Sample rate of each point's trajectory.csv [Hz]")
      ->check(CLI::Range(1.0, 1e6))
      ->default_val(250);
  cmd->add_flag("--plots", o->plots, "Pictures of every point (slow; the chart is always drawn)");
  cmd->add_flag("--quiet", o->quiet, "No line per point");
  cmd->footer(
      "Under MPI (mpirun -np N gaitopt library ...), rank 0 schedules and every rank solves; "
      "the folder must be on a file system all ranks share. A failed point is listed in "
      "index.csv with its status and does not stop the library. Exit codes: 0 done (failed "
      "points included), 2 bad input, 1 other failure.");
  cmd->callback([o] { runSubcommand([&] { runLibrary(*o); }); });
}

}  // namespace gaitopt::apps
