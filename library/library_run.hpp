#pragma once
/// @file library_run.hpp
/// One run of `gaitopt library`: the points not finished before, solved on an executor in the
/// order of the warm-start schedule (schedule.hpp), each row appended to the index as it comes.
#include <functional>
#include <string>

#include "library/library_index.hpp"
#include "library/library_point.hpp"
#include "library/schedule.hpp"
#include "parallel/executor.hpp"

namespace gaitopt::library {

/// What a run did: points finished in it (each once, second chances included), of those failed
/// at the end, and solves (second chances counted apart).
struct RunStats {
  int points = 0, failed = 0, solves = 0, workers = 0;
  double wall_time_s = 0;
  /// Points whose last row is of status "error": a point that could not be set up or written,
  /// or whose worker died and whose second chance did not solve it (a failure of the run, not a
  /// solver outcome), and the first one's message.
  int errors = 0;
  std::string first_error;
};

/// Sees each finished row, whether it was the point's second chance, and the points finished so
/// far in this run.
using RowReport = std::function<void(const IndexRow& row, bool second_chance, int points)>;

/// Solves the points `state` leaves unfinished, from the grid point nearest the base problem,
/// on `executor` (whose jobs answer with toJson(IndexRow)); appends every row to `index`.
RunStats solveLibrary(const LibrarySetup& setup, ScheduleState state, LibraryIndex& index,
                      parallel::Executor& executor, const RowReport& report);

}  // namespace gaitopt::library
