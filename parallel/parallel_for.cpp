#include "parallel/parallel_for.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <mutex>
#include <stdexcept>
#include <string>
#include <system_error>
#include <thread>
#include <vector>

namespace gaitopt::parallel {
namespace {

struct Queue {
  Queue(std::size_t count_, std::size_t chunk_) : count(count_), chunk(chunk_) {}
  std::size_t count, chunk;
  std::atomic<std::size_t> next{0}, done{0};
  std::exception_ptr error;
  std::mutex error_mutex;

  void work(const std::function<void(std::size_t)>& task) {
    for (std::size_t begin = next.fetch_add(chunk); begin < count; begin = next.fetch_add(chunk)) {
      const std::size_t end = std::min(begin + chunk, count);
      try {
        for (std::size_t i = begin; i < end; ++i) task(i);
      } catch (...) {
        const std::lock_guard lock(error_mutex);
        if (!error) error = std::current_exception();
        next = count;  // no worker takes a new block
      }
      done += end - begin;
    }
  }
};

}  // namespace

int resolveJobs(int jobs) {
  if (jobs > 0) return jobs;
  return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

void parallelFor(std::size_t count, int jobs, const std::function<void(std::size_t)>& task,
                 const ProgressFn& progress, std::size_t chunk) {
  if (jobs < 1) throw std::invalid_argument("parallelFor: jobs " + std::to_string(jobs) + " < 1");
  if (chunk < 1) throw std::invalid_argument("parallelFor: chunk must be >= 1");
  Queue queue(count, chunk);
  std::vector<std::thread> workers;
  try {
    for (int j = 0; j < jobs; ++j) workers.emplace_back([&] { queue.work(task); });
  } catch (const std::system_error& e) {
    // A process or thread limit: stop the started workers (never destroy a joinable thread,
    // which would std::terminate) and say what failed.
    queue.next = count;
    for (auto& w : workers) w.join();
    throw std::runtime_error("cannot start worker thread " + std::to_string(workers.size() + 1) +
                             " of " + std::to_string(jobs) + " (" + e.what() +
                             "): run with fewer --jobs");
  }
  while (progress && queue.done < count && queue.next < count) {
    progress(queue.done, count);
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  for (auto& w : workers) w.join();
  if (queue.error) std::rethrow_exception(queue.error);
  if (progress) progress(queue.done, count);
}

}  // namespace gaitopt::parallel
