#include "parallel/mpi_executor.hpp"

#include <mpi.h>

#include <chrono>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace gaitopt::parallel {
namespace {

enum Tag : int { kJobTag = 1, kResultTag = 2, kStopTag = 3 };

// Idle ranks poll instead of blocking in MPI_Recv: OpenMPI's blocking receive spins a core,
// which would take it from the solves of a rank sharing the machine.
constexpr auto kPollInterval = std::chrono::milliseconds(2);

/// A job or result on the wire: "<id>\n<payload>".
std::string encode(int id, const std::string& payload) {
  return std::to_string(id) + '\n' + payload;
}

JobResult decode(const std::string& text) {
  const std::size_t nl = text.find('\n');
  return {std::stoi(text.substr(0, nl)), text.substr(nl + 1)};
}

void send(const std::string& text, int rank, Tag tag) {
  MPI_Send(text.data(), static_cast<int>(text.size()), MPI_CHAR, rank, tag, MPI_COMM_WORLD);
}

/// The message waiting with `tag` from any rank, if there is one.
bool receive(Tag tag, std::string& text, int& source) {
  int flag = 0;
  MPI_Status status;
  MPI_Iprobe(MPI_ANY_SOURCE, tag, MPI_COMM_WORLD, &flag, &status);
  if (!flag) return false;
  int count = 0;
  MPI_Get_count(&status, MPI_CHAR, &count);
  text.assign(static_cast<std::size_t>(count), '\0');
  source = status.MPI_SOURCE;
  MPI_Recv(text.data(), count, MPI_CHAR, source, tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
  return true;
}

class MpiExecutor final : public Executor {
 public:
  MpiExecutor(const MpiSession& session, std::unique_ptr<Executor> local)
      : local_(std::move(local)),
        jobs_(local_->slots()),
        busy_(static_cast<std::size_t>(session.size()), 0) {}

  ~MpiExecutor() override {
    for (int rank = 1; rank < static_cast<int>(busy_.size()); ++rank) send("", rank, kStopTag);
  }
  MpiExecutor(const MpiExecutor&) = delete;
  MpiExecutor& operator=(const MpiExecutor&) = delete;

  int slots() const override { return jobs_ * static_cast<int>(busy_.size()); }

  /// Remote ranks first: rank 0's threads share their cores with the scheduler.
  void submit(Job job) override {
    for (std::size_t rank = 1; rank < busy_.size(); ++rank)
      if (busy_[rank] < jobs_) {
        ++busy_[rank];
        send(encode(job.id, job.payload), static_cast<int>(rank), kJobTag);
        return;
      }
    ++busy_[0];
    local_->submit(std::move(job));
  }

  JobResult next() override {
    for (;;) {
      if (auto r = tryNext()) return std::move(*r);
      std::this_thread::sleep_for(kPollInterval);
    }
  }

  std::optional<JobResult> tryNext() override {
    if (auto r = local_->tryNext()) {
      --busy_[0];
      return r;
    }
    std::string text;
    int source = 0;
    if (!receive(kResultTag, text, source)) return std::nullopt;
    --busy_[static_cast<std::size_t>(source)];
    return decode(text);
  }

 private:
  std::unique_ptr<Executor> local_;
  int jobs_;               ///< slots per rank
  std::vector<int> busy_;  ///< outstanding jobs per rank
};

}  // namespace

bool builtWithMpi() {
  return true;
}

MpiSession::MpiSession() {
  int provided = 0;
  if (MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided) != MPI_SUCCESS)
    throw std::runtime_error("MPI_Init_thread failed");
  if (provided < MPI_THREAD_FUNNELED) {
    MPI_Finalize();
    throw std::runtime_error("this MPI cannot run worker threads (no MPI_THREAD_FUNNELED)");
  }
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
}

MpiSession::~MpiSession() {
  MPI_Finalize();
}

std::unique_ptr<Executor> makeMpiExecutor(const MpiSession& session,
                                          std::unique_ptr<Executor> local) {
  return std::make_unique<MpiExecutor>(session, std::move(local));
}

void serveMpiJobs(const MpiSession& /*session*/, Executor& local) {
  int outstanding = 0;
  bool stopping = false;
  while (!stopping || outstanding > 0) {
    std::string text;
    int source = 0;
    bool idle = true;
    if (receive(kJobTag, text, source)) {
      local.submit([&] {
        const JobResult j = decode(text);
        return Job{j.id, j.payload};
      }());
      ++outstanding;
      idle = false;
    }
    if (auto r = local.tryNext()) {
      send(encode(r->id, r->payload), 0, kResultTag);
      --outstanding;
      idle = false;
    }
    if (receive(kStopTag, text, source)) stopping = true;
    if (idle) std::this_thread::sleep_for(kPollInterval);
  }
}

}  // namespace gaitopt::parallel
