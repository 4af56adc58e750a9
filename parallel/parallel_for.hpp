#pragma once
/// @file parallel_for.hpp
/// The one worker pool of the sweeps (impact map, stability sweeps): independent tasks spread
/// over std::thread workers that take the next index from a shared counter, so uneven task
/// times balance themselves. The result never depends on the number of workers: each task
/// writes only its own slot.
#include <cstddef>
#include <functional>

namespace gaitopt::parallel {

/// Called from the calling thread about every 100 ms while tasks run, and once at the end.
using ProgressFn = std::function<void(std::size_t done, std::size_t total)>;

/// Worker count for a user's choice: `jobs` when > 0, else every core (at least 1).
int resolveJobs(int jobs);

/// Runs task(i) for i in [0, count) on `jobs` workers (>= 1), in blocks of `chunk` indices
/// (large blocks keep the shared counter off the hot path of cheap tasks). The first exception
/// a task throws stops the other workers from taking new blocks and is rethrown here.
/// @throws std::invalid_argument when jobs < 1 or chunk < 1.
void parallelFor(std::size_t count, int jobs, const std::function<void(std::size_t)>& task,
                 const ProgressFn& progress = {}, std::size_t chunk = 1);

}  // namespace gaitopt::parallel
