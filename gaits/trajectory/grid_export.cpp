#include "gaits/trajectory/grid_export.hpp"

#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "config/config_error.hpp"

namespace gaitopt::gaits {
namespace {

std::vector<PhaseSwitch> switchesOf(const std::vector<Knot>& knots) {
  std::vector<PhaseSwitch> out;
  for (size_t k = 0; k + 1 < knots.size(); ++k)
    if (knots[k].t == knots[k + 1].t) out.push_back({knots[k], knots[k + 1]});
  return out;
}

}  // namespace

size_t gridSize(double end, double rate_hz) {
  // The largest i with i / rate_hz <= end: floor(end * rate) corrected for its rounding.
  auto n = static_cast<long>(std::floor(end * rate_hz));
  while (static_cast<double>(n + 1) / rate_hz <= end) ++n;
  while (n > 0 && static_cast<double>(n) / rate_hz > end) --n;
  return static_cast<size_t>(n) + 1;
}

void requireExportRate(double duration, double rate_hz) {
  const size_t n = gridSize(duration, rate_hz);
  if (n < kMinExportSamples)
    throw config::ConfigError(
        "export rate", "", 0,
        fmt::format("{:g} Hz samples the {:.4g} s step {} time(s), fewer than the {} an export "
                    "needs: use {:.4g} Hz or more",
                    rate_hz, duration, n, kMinExportSamples,
                    std::ceil(static_cast<double>(kMinExportSamples - 1) / duration)));
}

GridExport exportGrid(const Trajectory& traj, double rate_hz) {
  if (!(std::isfinite(rate_hz) && rate_hz > 0))
    throw std::invalid_argument(fmt::format("export rate is {} Hz, expected > 0", rate_hz));
  if (traj.knots().empty() || traj.startTime() != 0)
    throw std::invalid_argument(
        fmt::format("an exported step starts at t = 0, this one at {}", traj.startTime()));
  GridExport out{traj.robot(), traj.stepLength(),        rate_hz,
                 {},           switchesOf(traj.knots()), traj.knots().back()};
  requireExportRate(traj.endTime(), rate_hz);
  const size_t n = gridSize(traj.endTime(), rate_hz);
  out.samples.reserve(n);
  for (size_t i = 0; i < n; ++i) out.samples.push_back(traj.at(static_cast<double>(i) / rate_hz));
  return out;
}

Trajectory joinGrid(const std::string& robot, double step_length, const std::vector<Knot>& samples,
                    const std::vector<PhaseSwitch>& switches, const Knot& end) {
  std::vector<Knot> knots;
  size_t next = 0;  // next switch to put back
  const auto putSwitch = [&] {
    knots.push_back(switches[next].before);
    knots.push_back(switches[next].after);
    ++next;
  };
  for (const Knot& s : samples) {
    while (next < switches.size() && switches[next].before.t < s.t + kTimeTolerance) putSwitch();
    const bool at_switch =
        next > 0 && std::abs(switches[next - 1].before.t - s.t) <= kTimeTolerance;
    if (!at_switch && s.t < end.t - kTimeTolerance) knots.push_back(s);
  }
  while (next < switches.size()) putSwitch();
  knots.push_back(end);
  return Trajectory(robot, step_length, std::move(knots));
}

}  // namespace gaitopt::gaits
