#include "library/library_run.hpp"

#include <chrono>
#include <map>
#include <string>

#include "library/library_config.hpp"

namespace gaitopt::library {

RunStats solveLibrary(const LibrarySetup& setup, ScheduleState state, LibraryIndex& index,
                      parallel::Executor& executor, const RowReport& report) {
  RunStats stats;
  stats.workers = executor.slots();
  const ScheduleState before = state;
  const auto start = std::chrono::steady_clock::now();
  const int root = setup.grid.nearest(basePoint(setup.config));
  std::map<int, std::string> unsolved_errors;  // point -> the error of its last row
  runSchedule(setup.grid, root, state, executor,
              [&](const PointJob&, const parallel::JobResult& r) {
                const IndexRow row = indexRowFromJson(nlohmann::json::parse(r.payload));
                index.append(row);
                // A point's error counts while it is its last word: a worker killed under a
                // point that its second chance then solves leaves an error row, not an error.
                if (row.status == "error")
                  unsolved_errors.emplace(r.id, row.message);
                else
                  unsolved_errors.erase(r.id);
                const bool again = state.finished[static_cast<std::size_t>(r.id)];
                stats.points += again ? 0 : 1;
                ++stats.solves;
                if (report) report(row, again, stats.points);
                return row.converged;
              });
  stats.errors = static_cast<int>(unsolved_errors.size());
  if (!unsolved_errors.empty()) stats.first_error = unsolved_errors.begin()->second;
  for (std::size_t p = 0; p < state.solved.size(); ++p)
    stats.failed += !before.finished[p] && !state.solved[p] ? 1 : 0;
  stats.wall_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return stats;
}

}  // namespace gaitopt::library
