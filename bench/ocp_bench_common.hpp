#pragma once
/// @file ocp_bench_common.hpp
/// What the OCP benchmarks share (ocp_bench.cpp, ocp_study*.cpp): medians of repeated solves and
/// the derivative modes handed to Ipopt.
#include <algorithm>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "ocp/solve/ipopt_adapter.hpp"
#include "ocp/transcription/nlp.hpp"

namespace gaitopt::bench {

/// The middle element (the upper one of an even count); v must not be empty.
inline double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

/// Derivatives handed to Ipopt: (Hessian, Jacobian) as in ocp::SolverOptions.
inline const std::vector<std::pair<std::string, std::string>> kDerivativeModes = {
    {"exact", "exact"},
    {"limited-memory", "exact"},
    {"limited-memory", "finite-difference-values"}};

/// A solve repeated for its timing.
struct TimedSolve {
  ocp::SolveResult last;  ///< the last solve (all are identical but for the times)
  double wall = 0;        ///< median wall time [s]
  double callbacks = 0;   ///< median time in our callbacks [s]
  int solves = 0;         ///< how many solves the medians are of
};

/// Runs `solve` (a callable returning ocp::SolveResult) `repeats` times, stopping early once one
/// solve took longer than `long_solve_s` (a solve that slow is timed well enough once, and the
/// iterations do not change).
template <class Solve>
TimedSolve timeRepeated(const Solve& solve, int repeats,
                        double long_solve_s = std::numeric_limits<double>::infinity()) {
  std::vector<double> wall, callbacks;
  TimedSolve t;
  for (int k = 0; k < repeats; ++k) {
    t.last = solve();
    wall.push_back(t.last.wall_time_s);
    callbacks.push_back(t.last.callback_time_s);
    if (t.last.wall_time_s > long_solve_s) break;
  }
  t.wall = median(wall);
  t.callbacks = median(callbacks);
  t.solves = static_cast<int>(wall.size());
  return t;
}

/// `nlp` solved by Ipopt, timed as timeRepeated.
inline TimedSolve solveRepeated(const ocp::Nlp& nlp, const ocp::SolverOptions& options, int repeats,
                                double long_solve_s = std::numeric_limits<double>::infinity()) {
  return timeRepeated([&] { return ocp::solveWithIpopt(nlp, options); }, repeats, long_solve_s);
}

}  // namespace gaitopt::bench
