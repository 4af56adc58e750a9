#pragma once
/// @file executor.hpp
/// A work queue for jobs of uneven length (a gait solve takes 0.1 s or 20 s): the caller keeps
/// up to slots() jobs submitted and takes results as they finish, in completion order, so a
/// scheduler can decide the next job from what has finished (warm starts from solved
/// neighbours). Jobs and results are text (JSON), so the same scheduler drives threads in this
/// machine (process_executor.hpp) or the ranks of an MPI job (mpi_executor.hpp).
#include <functional>
#include <optional>
#include <string>

namespace gaitopt::parallel {

struct Job {
  int id = 0;
  std::string payload;  ///< what to do, e.g. {"point": 3, "warm_from": 2}
};

struct JobResult {
  int id = 0;
  std::string payload;  ///< what came of it
};

/// Runs one job on a worker. It must not throw: a failure is a result like any other.
using JobFn = std::function<std::string(const Job&)>;

class Executor {
 public:
  virtual ~Executor() = default;
  /// Jobs that can run at once.
  virtual int slots() const = 0;
  /// Starts `job`; at most slots() may be outstanding.
  virtual void submit(Job job) = 0;
  /// Blocks until an outstanding job finishes and returns its result.
  virtual JobResult next() = 0;
  /// A finished job's result if there is one, without waiting (for executors that poll
  /// several sources).
  virtual std::optional<JobResult> tryNext() = 0;
};

}  // namespace gaitopt::parallel
