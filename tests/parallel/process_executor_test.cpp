// ProcessExecutor: jobs run in forked worker processes and come back once each with their id;
// a worker that dies costs only its job (the on_crash result, naming the signal) and is
// replaced; the executor's bookkeeping errors; every worker is reaped by the destructor.
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <thread>

#include <gtest/gtest.h>

#include "parallel/process_executor.hpp"

namespace gaitopt::parallel {
namespace {

/// The worker's answer: "<2 * payload> <pid>"; payload "abort" aborts, "exit7" exits with 7.
std::string doubleIt(const Job& job) {
  if (job.payload == "abort") {
    const rlimit no_core{0, 0};
    ::setrlimit(RLIMIT_CORE, &no_core);  // no core file from the deliberate crash
    std::abort();
  }
  if (job.payload == "exit7") ::_exit(7);
  std::this_thread::sleep_for(std::chrono::milliseconds(3 + job.id % 5));
  return std::to_string(2 * std::stoi(job.payload)) + " " + std::to_string(::getpid());
}

std::string crashResult(const Job& job, const std::string& why) {
  return "crash " + std::to_string(job.id) + " " + why;
}

/// Whether a process with this pid still exists (a zombie counts).
bool exists(pid_t pid) {
  return ::kill(pid, 0) == 0 || errno != ESRCH;
}

struct Outcome {
  std::map<int, std::string> results;  ///< by id
  int duplicates = 0;
  int unknown = 0;
  std::set<pid_t> pids;
};

/// Runs jobs 0..n-1 (payload from `payload_of`) keeping every slot busy.
Outcome runJobs(ProcessExecutor& ex, int n, const std::function<std::string(int)>& payload_of) {
  Outcome o;
  int submitted = 0, outstanding = 0;
  while (submitted < n || outstanding > 0) {
    while (submitted < n && outstanding < ex.slots()) {
      ex.submit({submitted, payload_of(submitted)});
      ++submitted;
      ++outstanding;
    }
    const JobResult r = ex.next();
    --outstanding;
    if (r.id < 0 || r.id >= n) ++o.unknown;
    if (!o.results.emplace(r.id, r.payload).second) ++o.duplicates;
    const auto space = r.payload.rfind(' ');
    if (r.payload.rfind("crash", 0) != 0) o.pids.insert(std::stoi(r.payload.substr(space + 1)));
  }
  return o;
}

TEST(ProcessExecutor, RunsEveryJobOnceInWorkerProcesses) {
  std::set<pid_t> pids;
  {
    ProcessExecutor ex(3, doubleIt, crashResult);
    EXPECT_EQ(ex.slots(), 3);
    const Outcome o = runJobs(ex, 20, [](int id) { return std::to_string(100 + id); });
    EXPECT_EQ(o.duplicates, 0);
    EXPECT_EQ(o.unknown, 0);
    ASSERT_EQ(o.results.size(), 20u);
    for (const auto& [id, payload] : o.results)
      EXPECT_EQ(payload.substr(0, payload.find(' ')), std::to_string(2 * (100 + id))) << id;
    // Three workers, each a process of its own, none of them this one.
    EXPECT_EQ(o.pids.size(), 3u);
    EXPECT_EQ(o.pids.count(::getpid()), 0u);
    pids = o.pids;
    for (pid_t pid : pids) EXPECT_TRUE(exists(pid));
  }
  // The destructor closed the pipes and reaped every worker.
  for (pid_t pid : pids) EXPECT_FALSE(exists(pid)) << pid;
}

TEST(ProcessExecutor, ACrashedWorkerCostsOnlyItsJobAndIsReplaced) {
  ProcessExecutor ex(2, doubleIt, crashResult);
  const Outcome o = runJobs(ex, 12, [](int id) {
    return id == 3 ? std::string("abort") : id == 7 ? std::string("exit7") : std::to_string(id);
  });
  EXPECT_EQ(o.duplicates, 0);
  ASSERT_EQ(o.results.size(), 12u);
  EXPECT_EQ(o.results.at(3), "crash 3 worker process killed by signal " + std::to_string(SIGABRT));
  EXPECT_EQ(o.results.at(7), "crash 7 worker process exited with code 7");
  for (const auto& [id, payload] : o.results) {
    if (id == 3 || id == 7) continue;
    EXPECT_EQ(payload.substr(0, payload.find(' ')), std::to_string(2 * id)) << id;
  }
  // Two workers died and were replaced: more than two processes served the jobs, yet the
  // executor still has two slots and keeps working.
  EXPECT_GT(o.pids.size(), 2u);
  EXPECT_EQ(ex.slots(), 2);
  const Outcome more = runJobs(ex, 4, [](int id) { return std::to_string(id); });
  EXPECT_EQ(more.results.size(), 4u);
  EXPECT_EQ(more.results.at(2).substr(0, 1), "4");
}

TEST(ProcessExecutor, TryNextAndBookkeepingErrors) {
  ProcessExecutor ex(1, doubleIt, crashResult);
  EXPECT_EQ(ex.tryNext(), std::nullopt);  // nothing running
  EXPECT_THROW(ex.next(), std::logic_error);
  ex.submit({5, "21"});
  EXPECT_THROW(ex.submit({6, "1"}), std::logic_error);  // the only worker is busy
  // Polls until the job is done; tryNext never blocks.
  std::optional<JobResult> r;
  const auto start = std::chrono::steady_clock::now();
  while (!(r = ex.tryNext()) && std::chrono::steady_clock::now() - start < std::chrono::seconds(5))
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  ASSERT_TRUE(r.has_value());
  EXPECT_EQ(r->id, 5);
  EXPECT_EQ(r->payload.substr(0, 3), "42 ");
  EXPECT_EQ(ex.tryNext(), std::nullopt);
  EXPECT_THROW(ProcessExecutor(0, doubleIt, crashResult), std::invalid_argument);
}

TEST(ProcessExecutor, LargePayloadsCrossThePipeWhole) {
  // Bigger than a pipe buffer (64 KiB) both ways.
  ProcessExecutor ex(
      2, [](const Job& job) { return job.payload + job.payload; }, crashResult);
  const std::string big(300000, 'x');
  ex.submit({1, big + "1"});
  ex.submit({2, big + "2"});
  std::map<int, std::string> got;
  for (int k = 0; k < 2; ++k) {
    JobResult r = ex.next();
    got[r.id] = std::move(r.payload);
  }
  EXPECT_EQ(got.at(1), big + "1" + big + "1");
  EXPECT_EQ(got.at(2), big + "2" + big + "2");
}

// A run function that throws breaks the JobFn contract, but nothing stops it; the worker must
// still end as a crash instead of unwinding into its copy of the caller's stack (which would
// run the caller's code, here this test, in the worker); the guard below would turn that
// into "exited with code 99".
TEST(ProcessExecutor, AThrowingJobEndsItsWorkerAsACrash) {
  const pid_t parent = ::getpid();
  std::optional<JobResult> r;
  try {
    ProcessExecutor ex(
        1,
        [](const Job& job) -> std::string {
          if (job.payload == "throw") throw std::runtime_error("boom");
          return job.payload;
        },
        crashResult);
    ex.submit({1, "throw"});
    r = ex.next();
    ex.submit({2, "after"});
    EXPECT_EQ(ex.next().payload, "after");
  } catch (...) {
    if (::getpid() != parent) ::_exit(99);  // the exception escaped in the worker
    throw;
  }
  ASSERT_TRUE(r.has_value());
  EXPECT_EQ(r->id, 1);
  EXPECT_EQ(r->payload.rfind("crash 1 worker process ", 0), 0u) << r->payload;
  EXPECT_EQ(r->payload.find("99"), std::string::npos) << r->payload;
}

}  // namespace
}  // namespace gaitopt::parallel
