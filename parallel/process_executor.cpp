#include "parallel/process_executor.hpp"

#include <poll.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>
#include <system_error>

namespace gaitopt::parallel {
namespace {

/// Exit code of a worker whose job threw (EX_SOFTWARE of sysexits.h).
constexpr int kThrewExitCode = 70;

bool writeAll(int fd, const void* data, std::size_t size) {
  const auto* p = static_cast<const char*>(data);
  while (size > 0) {
    const ssize_t n = ::write(fd, p, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    p += n;
    size -= static_cast<std::size_t>(n);
  }
  return true;
}

bool readAll(int fd, void* data, std::size_t size) {
  auto* p = static_cast<char*>(data);
  while (size > 0) {
    const ssize_t n = ::read(fd, p, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;  // 0: the other end is closed
    p += n;
    size -= static_cast<std::size_t>(n);
  }
  return true;
}

/// A message on a pipe: id (int32), payload length (uint64), payload.
bool sendMessage(int fd, int id, const std::string& payload) {
  const std::int32_t id32 = id;
  const std::uint64_t size = payload.size();
  return writeAll(fd, &id32, sizeof id32) && writeAll(fd, &size, sizeof size) &&
         writeAll(fd, payload.data(), payload.size());
}

bool receiveMessage(int fd, int& id, std::string& payload) {
  std::int32_t id32 = 0;
  std::uint64_t size = 0;
  if (!readAll(fd, &id32, sizeof id32) || !readAll(fd, &size, sizeof size)) return false;
  payload.assign(size, '\0');
  id = id32;
  return readAll(fd, payload.data(), size);
}

void makePipe(int fds[2]) {
  if (::pipe(fds) != 0) throw std::system_error(errno, std::generic_category(), "pipe");
}

/// A worker's life: take a job, run it, send the result, until the job pipe closes. Nothing
/// may leave this function but _exit: an exception unwinding further would run the parent's
/// code (its copy of the caller's stack) inside the worker. A throwing job ends the worker,
/// and the parent reports the job as crashed.
[[noreturn]] void serve(int job_fd, int result_fd, const JobFn& run) {
  Job job;
  while (receiveMessage(job_fd, job.id, job.payload)) {
    std::string result;
    try {
      result = run(job);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "worker: job %d threw: %s\n", job.id, e.what());
      ::_exit(kThrewExitCode);
    } catch (...) {
      ::_exit(kThrewExitCode);
    }
    if (!sendMessage(result_fd, job.id, result)) ::_exit(1);
  }
  ::_exit(0);  // no atexit handlers or static destructors: they belong to the parent
}

std::string describeStatus(int status) {
  if (WIFSIGNALED(status)) return "killed by signal " + std::to_string(WTERMSIG(status));
  if (WIFEXITED(status)) return "exited with code " + std::to_string(WEXITSTATUS(status));
  return "stopped";
}

}  // namespace

ProcessExecutor::ProcessExecutor(int jobs, JobFn run, CrashFn on_crash)
    : run_(std::move(run)), on_crash_(std::move(on_crash)) {
  if (jobs < 1) throw std::invalid_argument("process executor: jobs " + std::to_string(jobs));
  // A job written to a worker that just died must be an error to handle, not a fatal signal.
  std::signal(SIGPIPE, SIG_IGN);
  workers_.resize(static_cast<std::size_t>(jobs));
  for (auto& w : workers_) spawn(w);
}

ProcessExecutor::~ProcessExecutor() {
  for (auto& w : workers_) retire(w);
}

void ProcessExecutor::spawn(Worker& w) {
  int job_pipe[2], result_pipe[2];
  makePipe(job_pipe);
  makePipe(result_pipe);
  const pid_t pid = ::fork();
  if (pid < 0) throw std::system_error(errno, std::generic_category(), "fork");
  if (pid == 0) {
    // The parent's ends of every pipe, so each worker sees EOF when the parent closes its own.
    for (const auto& other : workers_) {
      if (other.job_fd >= 0) ::close(other.job_fd);
      if (other.result_fd >= 0) ::close(other.result_fd);
    }
    ::close(job_pipe[1]);
    ::close(result_pipe[0]);
    serve(job_pipe[0], result_pipe[1], run_);
  }
  ::close(job_pipe[0]);
  ::close(result_pipe[1]);
  w = Worker{pid, job_pipe[1], result_pipe[0], std::nullopt};
}

void ProcessExecutor::retire(Worker& w) {
  ::close(w.job_fd);
  ::close(w.result_fd);
  int status = 0;
  while (::waitpid(w.pid, &status, 0) < 0 && errno == EINTR) {
  }
  w = Worker{};
}

void ProcessExecutor::submit(Job job) {
  for (auto& w : workers_)
    if (!w.job) {
      w.job = job;
      sendMessage(w.job_fd, job.id, job.payload);  // a dead worker shows up in collect()
      return;
    }
  throw std::logic_error("process executor: a job submitted while every worker is busy");
}

JobResult ProcessExecutor::next() {
  return *collect(-1);
}

std::optional<JobResult> ProcessExecutor::tryNext() {
  return collect(0);
}

JobResult ProcessExecutor::crashed(Worker& w) {
  const Job job = *w.job;
  const pid_t pid = w.pid;
  ::close(w.job_fd);
  ::close(w.result_fd);
  int status = 0;
  while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  w = Worker{};
  spawn(w);
  return {job.id, on_crash_(job, "worker process " + describeStatus(status))};
}

std::optional<JobResult> ProcessExecutor::collect(int timeout_ms) {
  std::vector<pollfd> fds;
  std::vector<Worker*> busy;
  for (auto& w : workers_)
    if (w.job) {
      fds.push_back({w.result_fd, POLLIN, 0});
      busy.push_back(&w);
    }
  if (busy.empty()) {
    if (timeout_ms < 0) throw std::logic_error("process executor: waiting with no job running");
    return std::nullopt;
  }
  int ready = 0;
  while ((ready = ::poll(fds.data(), fds.size(), timeout_ms)) < 0 && errno == EINTR) {
  }
  if (ready <= 0) return std::nullopt;
  for (std::size_t k = 0; k < fds.size(); ++k) {
    if (fds[k].revents == 0) continue;
    Worker& w = *busy[k];
    JobResult r;
    if (!receiveMessage(w.result_fd, r.id, r.payload)) return crashed(w);
    w.job.reset();
    return r;
  }
  return std::nullopt;
}

}  // namespace gaitopt::parallel
