#include "sim/scenario/walk_memory.hpp"

#include <algorithm>

#include <fmt/format.h>

#include "config/config_error.hpp"
#include "sim/walk/ground_registry.hpp"

namespace gaitopt::sim {
namespace {

/// A logged row's memory, the sample and its CSV text (measured: 200 steps on the LCP ground,
/// 1 kHz, 192 MB) [B].
constexpr double kBytesPerRow = 1500;
/// What a walk may keep [B].
constexpr double kWalkMemoryBudget = 4e9;

}  // namespace

void requireWalkFits(const Scenario& s, double step_time, double rate_hz,
                     const std::string& steps_option) {
  const double per_second = std::min(rate_hz, 1 / groundEntryOf(s.ground).time_step(s.ground));
  const double bytes = s.steps * step_time * per_second * kBytesPerRow;
  if (bytes <= kWalkMemoryBudget) return;
  throw config::ConfigError(
      steps_option, "", 0,
      fmt::format("{} steps of {:.3g} s at {:g} rows per second keep about {:.3g} GB in memory, "
                  "more than the {:g} GB a walk may take: walk fewer steps or log at a lower "
                  "rate",
                  s.steps, step_time, per_second, bytes / 1e9, kWalkMemoryBudget / 1e9));
}

}  // namespace gaitopt::sim
