// runSchedule on a fake executor (two slots, a queue; the points that "fail" decided by a set):
// the root goes first from the polynomial gait, every other point waits for a finished
// neighbour and starts from the nearest solved point at the time it is dispatched, failed
// points are finished but never warm starts, and a resumed run solves only what is left.
// Also the job text round trip.
#include <algorithm>
#include <array>
#include <deque>
#include <limits>
#include <map>
#include <set>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "library/schedule.hpp"

namespace gaitopt::library {
namespace {

/// A queue executor: jobs finish in submission order (FIFO) or newest first (LIFO), each
/// result "ok" or "fail" by the set of failing points.
class FakeExecutor final : public parallel::Executor {
 public:
  FakeExecutor(int slots, std::set<int> failing, bool lifo = false)
      : slots_(slots), failing_(std::move(failing)), lifo_(lifo) {}

  int slots() const override { return slots_; }
  void submit(parallel::Job job) override {
    if (static_cast<int>(queue_.size()) >= slots_) overfilled = true;
    queue_.push_back(std::move(job));
    max_outstanding = std::max(max_outstanding, static_cast<int>(queue_.size()));
    if (on_submit) on_submit(queue_.back());
  }
  parallel::JobResult next() override {
    if (queue_.empty()) throw std::logic_error("fake executor: next() with nothing running");
    parallel::Job job = lifo_ ? queue_.back() : queue_.front();
    lifo_ ? queue_.pop_back() : queue_.pop_front();
    return {job.id, failing_.count(job.id) ? "fail" : "ok"};
  }
  std::optional<parallel::JobResult> tryNext() override {
    if (queue_.empty()) return std::nullopt;
    return next();
  }

  std::function<void(const parallel::Job&)> on_submit;
  bool overfilled = false;
  int max_outstanding = 0;

 private:
  int slots_;
  std::set<int> failing_;
  bool lifo_;
  std::deque<parallel::Job> queue_;
};

/// One run of the schedule, checking at every dispatch what the scheduler may know then.
struct ScheduleRun {
  std::vector<PointJob> jobs;  ///< in dispatch order
  ScheduleState state;
  std::vector<std::string> violations;
  bool overfilled = false;
  int max_outstanding = 0;
};

ScheduleState freshState(const Grid& g) {
  const auto n = static_cast<std::size_t>(g.size());
  return {std::vector<bool>(n, false), std::vector<bool>(n, false)};
}

ScheduleRun runWith(const Grid& g, int root, const std::set<int>& failing, ScheduleState state,
                    bool lifo = false, int slots = 2) {
  ScheduleRun run;
  run.state = std::move(state);
  // What has been reported finished/solved so far, as the test sees it.
  std::vector<bool> finished = run.state.finished, solved = run.state.solved;
  std::set<int> outstanding;
  std::map<int, int> failed_from;  // second chances: a failed point, retried once from elsewhere
  std::set<int> retried;
  FakeExecutor ex(slots, failing, lifo);
  ex.on_submit = [&](const parallel::Job& job) {
    const PointJob pj = decodeJob(job.payload);
    const auto violation = [&](const std::string& what) {
      run.violations.push_back("point " + std::to_string(pj.point) + ": " + what);
    };
    if (pj.point != job.id) violation("job id differs from the point");
    const bool second_chance = finished[static_cast<std::size_t>(pj.point)];
    if (second_chance) {
      const auto first = failed_from.find(pj.point);
      if (first == failed_from.end() || pj.warm_from < 0 || pj.warm_from == first->second ||
          !retried.insert(pj.point).second)
        violation("dispatched although finished, and not as a second chance");
    }
    if (!outstanding.insert(pj.point).second) violation("dispatched twice at once");
    bool neighbour_done = pj.point == root;
    for (int q : g.neighbours(pj.point)) neighbour_done = neighbour_done || finished[q];
    if (!neighbour_done) violation("dispatched before a neighbour finished");
    double best = std::numeric_limits<double>::infinity();
    for (int q = 0; q < g.size(); ++q)
      if (solved[static_cast<std::size_t>(q)]) best = std::min(best, g.distance(pj.point, q));
    if (pj.warm_from < 0) {
      if (best < std::numeric_limits<double>::infinity())
        violation("started from the polynomial gait with a solved point available");
    } else if (!solved[static_cast<std::size_t>(pj.warm_from)]) {
      violation("warm start from unsolved point " + std::to_string(pj.warm_from));
    } else if (!second_chance && g.distance(pj.point, pj.warm_from) != best) {
      violation("warm start from " + std::to_string(pj.warm_from) + " is not the nearest");
    }
    run.jobs.push_back(pj);
  };
  runSchedule(g, root, run.state, ex, [&](const PointJob& job, const parallel::JobResult& r) {
    EXPECT_EQ(job.point, r.id);
    outstanding.erase(job.point);
    const bool ok = r.payload == "ok";
    if (!ok) failed_from.emplace(job.point, job.warm_from);
    finished[static_cast<std::size_t>(job.point)] = true;
    solved[static_cast<std::size_t>(job.point)] = ok;
    return ok;
  });
  run.overfilled = ex.overfilled;
  run.max_outstanding = ex.max_outstanding;
  return run;
}

std::vector<int> points(const ScheduleRun& run) {
  std::vector<int> p;
  for (const auto& j : run.jobs) p.push_back(j.point);
  std::sort(p.begin(), p.end());
  return p;
}

std::vector<int> range(int n) {
  std::vector<int> v(static_cast<std::size_t>(n));
  for (int k = 0; k < n; ++k) v[static_cast<std::size_t>(k)] = k;
  return v;
}

/// 4 speeds x 3 step lengths x 2 slopes.
Grid grid4x3x2() {
  return Grid({{{0.3, 0.4, 0.5, 0.6}, {0.3, 0.35, 0.4}, {-0.02, 0.02}}});
}

const PointJob* jobOf(const ScheduleRun& run, int point) {
  for (const auto& j : run.jobs)
    if (j.point == point) return &j;
  return nullptr;
}

TEST(Schedule, AllSolvedRootFirstNearestWarmStarts) {
  const Grid g = grid4x3x2();
  for (bool lifo : {false, true}) {
    const int root = 8;  // (1, 1, 0): inside
    const ScheduleRun run = runWith(g, root, {}, freshState(g), lifo);
    EXPECT_TRUE(run.violations.empty()) << run.violations.front();
    ASSERT_EQ(run.jobs.size(), 24u);
    EXPECT_EQ(points(run), range(24));  // each point exactly once
    EXPECT_EQ(run.jobs.front().point, root);
    EXPECT_EQ(run.jobs.front().warm_from, -1);
    for (std::size_t k = 1; k < run.jobs.size(); ++k) {
      EXPECT_GE(run.jobs[k].warm_from, 0) << "job " << k;
      // With nothing failing, a neighbour is always solved: every warm start is one step.
      EXPECT_DOUBLE_EQ(g.distance(run.jobs[k].point, run.jobs[k].warm_from), 1.0);
    }
    EXPECT_FALSE(run.overfilled);
    EXPECT_EQ(run.max_outstanding, 2);  // both slots are used once the wave has spread
    EXPECT_TRUE(std::all_of(run.state.finished.begin(), run.state.finished.end(),
                            [](bool b) { return b; }));
    EXPECT_TRUE(
        std::all_of(run.state.solved.begin(), run.state.solved.end(), [](bool b) { return b; }));
  }
}

TEST(Schedule, FailedPointsAreFinishedButNeverWarmStarts) {
  // 3 x 3 x 1, root 0 (corner). 1 and 3 fail: 4, whose neighbours 1 and 3 failed, starts from
  // 0 (sqrt 2 away), the nearest solved point further away. 1 and 3, first started from 0, are
  // tried once more from the nearest other solved point (the fake fails them again).
  const Grid g({{{0.3, 0.4, 0.5}, {0.3, 0.35, 0.4}, {0.0}}});
  const std::set<int> failing = {1, 3};
  const ScheduleRun run = runWith(g, 0, failing, freshState(g));
  EXPECT_TRUE(run.violations.empty()) << run.violations.front();
  EXPECT_EQ(points(run), (std::vector<int>{0, 1, 1, 2, 3, 3, 4, 5, 6, 7, 8}));
  for (int p : {1, 3}) {
    const auto second = std::find_if(run.jobs.rbegin(), run.jobs.rend(),
                                     [p](const PointJob& j) { return j.point == p; });
    EXPECT_NE(second->warm_from, 0) << p;  // not where it failed from first
    EXPECT_GE(second->warm_from, 0) << p;
  }
  for (const auto& j : run.jobs) EXPECT_FALSE(failing.count(j.warm_from)) << j.point;
  const PointJob* centre = jobOf(run, 4);
  ASSERT_NE(centre, nullptr);
  EXPECT_EQ(centre->warm_from, 0);
  for (int p = 0; p < 9; ++p) {
    EXPECT_TRUE(run.state.finished[static_cast<std::size_t>(p)]) << p;
    EXPECT_EQ(run.state.solved[static_cast<std::size_t>(p)], failing.count(p) == 0) << p;
  }
}

TEST(Schedule, AFailedRootLeavesItsNeighboursThePolynomialGaitThenGetsASecondChance) {
  // Speeds only; the root in the middle fails, so both neighbours start from -1; the ends
  // start from whichever neighbour solved; the root is tried once more, warm, from a solved
  // neighbour (it fails again here: the fake fails it whatever the start).
  const Grid g({{{0.3, 0.4, 0.5, 0.6, 0.7}, {0.35}, {0.0}}});
  const ScheduleRun run = runWith(g, 2, {2}, freshState(g));
  EXPECT_TRUE(run.violations.empty()) << run.violations.front();
  ASSERT_EQ(run.jobs.size(), 6u);
  EXPECT_EQ(run.jobs[0].point, 2);
  EXPECT_EQ(run.jobs[0].warm_from, -1);
  const auto retry = std::find_if(run.jobs.begin() + 1, run.jobs.end(),
                                  [](const PointJob& j) { return j.point == 2; });
  ASSERT_NE(retry, run.jobs.end());
  EXPECT_TRUE(retry->warm_from == 1 || retry->warm_from == 3) << retry->warm_from;
  EXPECT_EQ(jobOf(run, 1)->warm_from, -1);
  EXPECT_EQ(jobOf(run, 3)->warm_from, -1);
  EXPECT_EQ(jobOf(run, 0)->warm_from, 1);
  EXPECT_EQ(jobOf(run, 4)->warm_from, 3);
  EXPECT_FALSE(run.state.solved[2]);
  EXPECT_TRUE(run.state.finished[2]);
}

TEST(Schedule, EverythingFailingStillFinishesEveryPointOnce) {
  const Grid g = grid4x3x2();
  std::set<int> all;
  for (int p = 0; p < g.size(); ++p) all.insert(p);
  const ScheduleRun run = runWith(g, 0, all, freshState(g));
  EXPECT_TRUE(run.violations.empty()) << run.violations.front();
  EXPECT_EQ(points(run), range(24));
  for (const auto& j : run.jobs) EXPECT_EQ(j.warm_from, -1) << j.point;
  EXPECT_EQ(std::count(run.state.solved.begin(), run.state.solved.end(), true), 0);
}

TEST(Schedule, AResumedRunSolvesOnlyTheUnfinishedPoints) {
  // 3 x 3 x 1: 0, 1, 3, 4 solved before, 5 failed before (not retried); root 4 is done.
  const Grid g({{{0.3, 0.4, 0.5}, {0.3, 0.35, 0.4}, {0.0}}});
  ScheduleState state = freshState(g);
  for (int p : {0, 1, 3, 4}) state.finished[p] = state.solved[p] = true;
  state.finished[5] = true;
  const ScheduleRun run = runWith(g, 4, {}, state);
  EXPECT_TRUE(run.violations.empty()) << run.violations.front();
  EXPECT_EQ(points(run), (std::vector<int>{2, 6, 7, 8}));
  // 2 (0,2): neighbours 1 solved and 5 failed: from 1. 6 (2,0): from 3. 7 (2,1): from 4.
  EXPECT_EQ(jobOf(run, 2)->warm_from, 1);
  EXPECT_EQ(jobOf(run, 6)->warm_from, 3);
  EXPECT_EQ(jobOf(run, 7)->warm_from, 4);
  EXPECT_FALSE(run.state.solved[5]);
  // Nothing left: no job at all.
  const ScheduleRun again = runWith(g, 4, {}, run.state);
  EXPECT_TRUE(again.jobs.empty());
}

TEST(Schedule, OneSlotSolvesAsAWavefrontFromTheRoot) {
  const Grid g({{{0.3, 0.4, 0.5, 0.6, 0.7}, {0.35}, {0.0}}});
  const ScheduleRun run = runWith(g, 1, {}, freshState(g), false, 1);
  EXPECT_TRUE(run.violations.empty()) << run.violations.front();
  EXPECT_EQ(run.max_outstanding, 1);
  // Ties (0 and 2 both one step from the solved root) go to the lower index.
  std::vector<int> order;
  for (const auto& j : run.jobs) order.push_back(j.point);
  EXPECT_EQ(order, (std::vector<int>{1, 0, 2, 3, 4}));
}

TEST(ScheduleJob, EncodeDecodeRoundTrip) {
  for (const PointJob job : {PointJob{0, -1}, PointJob{17, 3}, PointJob{123456, 123455}}) {
    const PointJob back = decodeJob(encodeJob(job));
    EXPECT_EQ(back.point, job.point);
    EXPECT_EQ(back.warm_from, job.warm_from);
  }
  EXPECT_EQ(decodeJob(R"({"warm_from": 2, "point": 5})").point, 5);
}

TEST(ScheduleJob, BadTextThrowsInvalidArgument) {
  for (const char* text : {"", "not json", "[1, 2]", "{\"point\": 3}", "{\"warm_from\": 1}",
                           "{\"point\": \"3\", \"warm_from\": 1}", "{\"point\": 3, "}) {
    EXPECT_THROW(decodeJob(text), std::invalid_argument) << text;
  }
  try {
    decodeJob("oops");
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("not a library job: 'oops'"), std::string::npos)
        << e.what();
  }
}

// The size of the README's paper estimate: a 22 x 22 x 21 grid (10,164 points) on 2048 slots.
// The scheduler must not scan the grid per dispatch (that was 10^12 operations); with the
// frontier the whole schedule takes well under a second (Release).
TEST(Schedule, TenThousandPointsOnTwoThousandSlots) {
  std::array<std::vector<double>, 3> axes;
  for (int a = 0; a < 3; ++a)
    for (int k = 0; k < (a == 2 ? 21 : 22); ++k) axes[a].push_back(0.1 + 0.01 * k);
  const Grid g(axes);
  ASSERT_EQ(g.size(), 10164);
  FakeExecutor ex(2048, {});
  ScheduleState state = freshState(g);
  int jobs = 0, warm_from_neighbour = 0;
  ex.on_submit = [&](const parallel::Job& job) {
    const PointJob pj = decodeJob(job.payload);
    ++jobs;
    if (pj.warm_from >= 0 && g.distance(pj.point, pj.warm_from) == 1) ++warm_from_neighbour;
  };
  const int root = g.nearest({0.2, 0.2, 0.2});
  runSchedule(g, root, state, ex, [](const PointJob&, const parallel::JobResult&) { return true; });
  EXPECT_EQ(jobs, g.size());
  EXPECT_EQ(warm_from_neighbour, g.size() - 1);  // all but the root start one step away
  EXPECT_TRUE(std::all_of(state.solved.begin(), state.solved.end(), [](bool b) { return b; }));
}

}  // namespace
}  // namespace gaitopt::library
