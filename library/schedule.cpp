#include "library/schedule.hpp"

#include <map>
#include <set>
#include <stdexcept>
#include <tuple>

#include <nlohmann/json.hpp>

namespace gaitopt::library {
namespace {

/// The nearest solved point other than `except` (-1 when there is none): a solved neighbour
/// if there is one (nothing is nearer), else a scan of the grid.
int nearestSolved(const Grid& grid, const ScheduleState& s, int p, int except = -1) {
  const auto usable = [&](int q) { return q != except && s.solved[static_cast<std::size_t>(q)]; };
  int best = -1;
  for (int q : grid.neighbours(p))
    if (usable(q) && (best < 0 || q < best)) best = q;
  if (best >= 0) return best;
  for (int q = 0; q < grid.size(); ++q)
    if (usable(q) && (best < 0 || grid.distance(p, q) < grid.distance(p, best))) best = q;
  return best;
}

/// The points waiting to be solved, best first, updated as points finish: a point is ready
/// when a neighbour has finished (or it is the root); ready points with a solved neighbour go
/// first, then those nearest the root. Incremental, so a dispatch costs O(log n) on grids of
/// thousands of points rather than a scan of the grid.
class Frontier {
 public:
  Frontier(const Grid& grid, const ScheduleState& s, int root) : grid_(grid), root_(root) {
    for (int p = 0; p < grid.size(); ++p) update(s, p);
  }

  /// Re-ranks the unfinished neighbours of a point that just finished.
  void finished(const ScheduleState& s, int p) {
    for (int q : grid_.neighbours(p)) update(s, q);
  }

  /// Marks a point as dispatched, so it is not ranked again until it finishes.
  void dispatched(int p) { taken_.insert(p); }
  void returned(int p) { taken_.erase(p); }

  /// The best ready point, taken off the frontier.
  std::optional<int> take() {
    if (ready_.empty()) return std::nullopt;
    const int p = std::get<2>(*ready_.begin());
    ready_.erase(ready_.begin());
    keys_.erase(p);
    return p;
  }

 private:
  using Key = std::tuple<int, double, int>;  // (no solved neighbour, distance to root, point)

  void update(const ScheduleState& s, int p) {
    if (const auto it = keys_.find(p); it != keys_.end()) {
      ready_.erase(it->second);
      keys_.erase(it);
    }
    if (s.finished[static_cast<std::size_t>(p)] || taken(p)) return;
    bool ready = p == root_, solved_neighbour = false;
    for (int q : grid_.neighbours(p)) {
      ready = ready || s.finished[static_cast<std::size_t>(q)];
      solved_neighbour = solved_neighbour || s.solved[static_cast<std::size_t>(q)];
    }
    if (!ready) return;
    const Key key{solved_neighbour ? 0 : 1, grid_.distance(p, root_), p};
    ready_.insert(key);
    keys_[p] = key;
  }

  bool taken(int p) const { return taken_.count(p) > 0; }

  const Grid& grid_;
  int root_;
  std::set<Key> ready_;
  std::map<int, Key> keys_;
  std::set<int> taken_;
};

/// A failed point is tried once more, from the nearest solved point it has not started from,
/// as soon as there is one: a cold start that failed before anything was solved (the base
/// problem's own point may be the hard one), or a warm start from a neighbour on another
/// branch of optima. `waiting` maps each such point to where its first attempt started.
std::optional<PointJob> secondChance(const Grid& grid, const ScheduleState& s,
                                     std::map<int, int>& waiting) {
  for (auto it = waiting.begin(); it != waiting.end(); ++it) {
    const int from = nearestSolved(grid, s, it->first, it->second);
    if (from < 0) continue;
    const PointJob job{it->first, from};
    waiting.erase(it);  // once only
    return job;
  }
  return std::nullopt;
}

}  // namespace

std::string encodeJob(const PointJob& job) {
  return nlohmann::json{{"point", job.point}, {"warm_from", job.warm_from}}.dump();
}

PointJob decodeJob(const std::string& text) {
  try {
    const auto j = nlohmann::json::parse(text);
    return {j.at("point").get<int>(), j.at("warm_from").get<int>()};
  } catch (const nlohmann::json::exception& e) {
    throw std::invalid_argument("not a library job: '" + text + "': " + e.what());
  }
}

void runSchedule(const Grid& grid, int root, ScheduleState& state, parallel::Executor& executor,
                 const OnFinished& on_finished) {
  Frontier frontier(grid, state, root);
  std::map<int, int> waiting;  // failed once, awaiting a second chance
  std::set<int> retried;
  std::map<int, PointJob> outstanding;
  for (;;) {
    while (static_cast<int>(outstanding.size()) < executor.slots()) {
      auto job = secondChance(grid, state, waiting);
      if (job) {
        retried.insert(job->point);
      } else if (const auto p = frontier.take()) {
        job = PointJob{*p, nearestSolved(grid, state, *p)};
      } else {
        break;
      }
      frontier.dispatched(job->point);
      outstanding[job->point] = *job;
      executor.submit({job->point, encodeJob(*job)});
    }
    if (outstanding.empty()) return;  // nothing running and nothing ready: all finished
    const parallel::JobResult r = executor.next();
    const PointJob job = outstanding.at(r.id);
    outstanding.erase(r.id);
    const auto k = static_cast<std::size_t>(r.id);
    state.solved[k] = on_finished(job, r);
    state.finished[k] = true;
    frontier.returned(r.id);
    frontier.finished(state, r.id);
    if (!state.solved[k] && !retried.count(r.id)) waiting[r.id] = job.warm_from;
  }
}

}  // namespace gaitopt::library
