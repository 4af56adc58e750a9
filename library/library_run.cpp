#include "library/library_run.hpp"

#include <chrono>

#include "library/library_config.hpp"

namespace gaitopt::library {

RunStats solveLibrary(const LibrarySetup& setup, ScheduleState state, LibraryIndex& index,
                      parallel::Executor& executor, const RowReport& report) {
  RunStats stats;
  stats.workers = executor.slots();
  const ScheduleState before = state;
  const auto start = std::chrono::steady_clock::now();
  const int root = setup.grid.nearest(basePoint(setup.config));
  runSchedule(setup.grid, root, state, executor,
              [&](const PointJob&, const parallel::JobResult& r) {
                const IndexRow row = indexRowFromJson(nlohmann::json::parse(r.payload));
                index.append(row);
                if (row.status == "error" && stats.errors++ == 0) stats.first_error = row.message;
                const bool again = state.finished[static_cast<std::size_t>(r.id)];
                stats.points += again ? 0 : 1;
                ++stats.solves;
                if (report) report(row, again, stats.points);
                return row.converged;
              });
  for (std::size_t p = 0; p < state.solved.size(); ++p)
    stats.failed += !before.finished[p] && !state.solved[p] ? 1 : 0;
  stats.wall_time_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return stats;
}

}  // namespace gaitopt::library
