#include "library/library_point.hpp"

#include <chrono>
#include <cmath>
#include <filesystem>
#include <optional>

#include <fmt/format.h>

#include "gaits/export/metrics.hpp"
#include "gaits/polynomial/retime.hpp"
#include "gaits/trajectory/trajectory_csv.hpp"
#include "io/output/output_folder.hpp"
#include "library/point_problem.hpp"
#include "ocp/guess/initial_guess.hpp"

namespace gaitopt::library {
namespace {

/// The polynomial gait of the point, or why it cannot be realised there.
struct PolyGuess {
  std::optional<gaits::Trajectory> traj;
  std::string error;
};

PolyGuess polyGuess(const PointProblem& pp) {
  try {
    return {ocp::polynomialGuess(pp.model, pp.guess), ""};
  } catch (const std::domain_error& e) {
    return {std::nullopt, std::string("polynomial gait: ") + e.what()};
  }
}

/// A solve and what it cost; iterations and times add up over the attempts.
struct Attempts {
  std::optional<ocp::GaitSolution> solution;
  ocp::OcpConfig config;  ///< the last attempt's problem, its continuation on or off
  int iterations = 0;
  double time_s = 0;

  /// The library's schedule is the continuation between points (schedule.hpp): the base
  /// config's own path to one problem runs only when asked for.
  void run(const PointProblem& pp, const gaits::Trajectory& guess, bool continuation) {
    config = pp.config;
    config.continuation.enabled = continuation;
    solution = ocp::solveGait(pp.model, config, guess);
    iterations += solution->result.iterations;
    time_s += solution->result.wall_time_s;
  }
  bool solved() const { return solution && solution->result.success; }
};

/// From the neighbour's gait if the schedule names one, else (or if that fails) from the
/// polynomial gait, and last, where the base config has a continuation (a problem like the
/// ensemble's, which its polynomial gait does not reach directly), along it. The cheapest start
/// comes first: a library whose points all converge directly never runs a continuation.
void solve(const LibrarySetup& setup, const PointJob& job, const PointProblem& pp,
           const PolyGuess& poly, Attempts& a, IndexRow& row) {
  if (job.warm_from >= 0) {
    row.start = "warm:" + setup.grid.point(job.warm_from).name;
    try {
      const gaits::Trajectory neighbour =
          gaits::readTrajectoryCsv(setup.pointDir(job.warm_from) + "/trajectory.csv", pp.model);
      a.run(pp, gaits::retimed(neighbour, phaseDurations(pp.config), pp.config.step_length), false);
    } catch (const std::exception& e) {  // a neighbour's file damaged since: start cold
      if (!poly.traj) throw;
      row.message = std::string("warm start unusable: ") + e.what();
    }
    if (a.solved() || !poly.traj) return;
    row.start += ",polynomial";
  } else {
    if (!poly.traj) throw std::domain_error(poly.error);
    row.start = "polynomial";
  }
  a.run(pp, *poly.traj, false);
  if (a.solved() || !setup.continuation || !pp.config.continuation.enabled) return;
  row.start += ",continuation";
  a.run(pp, *poly.traj, true);
}

void record(const LibrarySetup& setup, const PointProblem& pp, const Attempts& a,
            const std::string& dir, IndexRow& row) {
  const ocp::GaitSolution& s = *a.solution;
  row.status = s.result.status;
  row.converged = s.result.success;
  row.cost = s.result.cost;
  row.iterations = a.iterations;
  row.solve_time_s = a.time_s;
  ocp::GaitResultOptions options = setup.result;
  options.config_path = setup.config.path;
  // The point's values of the config axes, as `--set` would have given them.
  for (std::size_t a = 0; a < row.config_values.size(); ++a)
    options.config_overrides.push_back(
        fmt::format("{}={}", setup.config.config_axes[a].key, row.config_values[a]));
  if (!row.converged) {
    row.message = ocp::writeFailedResult(options, pp.model, a.config, s, dir + ".failed");
    return;
  }
  io::OutputFolder(dir, {}, "--out", "gait").write([&](const std::string& staging) {
    const auto summary = ocp::writeGaitResult(options, pp.model, a.config, s, nullptr, staging);
    row.cost_of_transport = summary.at("cost_of_transport").get<double>();
  });
  ocp::removeFailedResult(dir + ".failed");  // a retried point's old failure
}

/// A row for the point with nothing known yet.
IndexRow emptyRow(const GridPoint& p) {
  IndexRow row;
  row.point = p.name;
  row.speed = p.values[kSpeed];
  row.step_length = p.values[kStepLength];
  row.slope = p.values[kSlope];
  row.config_values.assign(p.values.begin() + kWalkAxes, p.values.end());
  row.cost = row.cost_of_transport = row.poly_cost_of_transport = std::nan("");
  return row;
}

}  // namespace

std::string LibrarySetup::pointDir(int point) const {
  return out_dir + "/points/" + grid.point(point).name;
}

IndexRow crashedPointRow(const LibrarySetup& setup, const PointJob& job, const std::string& why) {
  IndexRow row = emptyRow(setup.grid.point(job.point));
  row.status = "error";
  row.message = why;
  return row;
}

IndexRow solveLibraryPoint(const LibrarySetup& setup, const PointJob& job) {
  IndexRow row = emptyRow(setup.grid.point(job.point));
  const auto start = std::chrono::steady_clock::now();
  Attempts attempts;
  try {
    const GridPoint& point = setup.grid.point(job.point);
    const PointProblem pp = pointProblem(baseAt(setup.config, point), point.walk());
    const PolyGuess poly = polyGuess(pp);
    if (poly.traj) row.poly_cost_of_transport = gaits::costOfTransport(*poly.traj, pp.model);
    solve(setup, job, pp, poly, attempts, row);
    record(setup, pp, attempts, setup.pointDir(job.point), row);
  } catch (const std::exception& e) {
    // Whatever got this far (a solve that converged before its folder could not be written) is
    // lost: the point is failed, never converged.
    row.status = "error";
    row.converged = false;
    row.message = e.what();
    row.solve_time_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  return row;
}

}  // namespace gaitopt::library
