#pragma once
/// @file process_executor.hpp
/// The executor of one machine: `jobs` worker processes forked at construction, each taking
/// one job at a time through a pipe. Processes, not threads, because a gait solve runs MUMPS
/// (Ipopt's linear solver in Debian), whose sequential build keeps global state: two solves in
/// threads of one process corrupt each other ("PB allocation in DMUMPS_LOAD_INIT"). A worker
/// that dies (a crash inside a solve) costs only its job: the job's result is made by
/// `on_crash` and a new worker takes its place.
#include <sys/types.h>

#include <vector>

#include "parallel/executor.hpp"

namespace gaitopt::parallel {

/// The result of a job whose worker died, from the job and why (e.g. "killed by signal 11").
using CrashFn = std::function<std::string(const Job&, const std::string& why)>;

class ProcessExecutor final : public Executor {
 public:
  /// Forks the workers; `run` runs in them, on their copy of the caller's memory. Create it
  /// before starting threads or MPI in the caller (fork copies only the calling thread).
  /// @throws std::invalid_argument when jobs < 1, std::system_error when fork or pipe fail.
  ProcessExecutor(int jobs, JobFn run, CrashFn on_crash);
  /// Closes the job pipes (workers exit after their job) and waits for every worker.
  ~ProcessExecutor() override;
  ProcessExecutor(const ProcessExecutor&) = delete;
  ProcessExecutor& operator=(const ProcessExecutor&) = delete;

  int slots() const override { return static_cast<int>(workers_.size()); }
  void submit(Job job) override;
  JobResult next() override;
  std::optional<JobResult> tryNext() override;

 private:
  struct Worker {
    pid_t pid = -1;
    int job_fd = -1;     ///< parent writes jobs here
    int result_fd = -1;  ///< parent reads results here
    std::optional<Job> job;
  };

  void spawn(Worker& w);
  void retire(Worker& w);
  /// Waits up to `timeout_ms` (-1: forever) for a busy worker's result.
  std::optional<JobResult> collect(int timeout_ms);
  JobResult crashed(Worker& w);

  JobFn run_;
  CrashFn on_crash_;
  std::vector<Worker> workers_;
};

}  // namespace gaitopt::parallel
