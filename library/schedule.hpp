#pragma once
/// @file schedule.hpp
/// The order in which a gait library is solved. Each point starts from the nearest point
/// already solved (a warm start: neighbouring gaits differ little, so the solve is short and
/// lands on the same branch of optima), so points are handed out as a wavefront from the root
/// (the base problem's own point, started from the polynomial gait): a point is ready once a
/// neighbour has finished. A failed point is finished too, so the wave goes around it, and its
/// neighbours start from the nearest solved point further away, or from the polynomial gait.
#include <functional>
#include <vector>

#include "library/grid.hpp"
#include "parallel/executor.hpp"

namespace gaitopt::library {

/// What the solver of a point is asked: solve `point`, starting from the solution of
/// `warm_from` (-1: from the polynomial gait).
struct PointJob {
  int point = 0;
  int warm_from = -1;
};

struct ScheduleState {
  std::vector<bool> finished;  ///< solved, or failed and not to be retried
  std::vector<bool> solved;    ///< converged: usable as a warm start
};

/// Reports a finished job; returns whether the point was solved.
using OnFinished = std::function<bool(const PointJob&, const parallel::JobResult&)>;

/// The job text of a point (JSON), and back.
std::string encodeJob(const PointJob& job);
/// @throws std::invalid_argument for text that is not a job.
PointJob decodeJob(const std::string& text);

/// Solves every point not yet finished on `executor`, keeping all its slots busy with ready
/// points, until all are finished.
void runSchedule(const Grid& grid, int root, ScheduleState& state, parallel::Executor& executor,
                 const OnFinished& on_finished);

}  // namespace gaitopt::library
