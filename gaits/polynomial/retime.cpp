#include "gaits/polynomial/retime.hpp"

#include <stdexcept>

#include <fmt/format.h>

namespace gaitopt::gaits {

Trajectory retimed(const Trajectory& traj, const std::vector<double>& durations,
                   double step_length) {
  const auto phases = traj.phaseDurations();
  if (phases.size() != durations.size())
    throw std::invalid_argument(
        fmt::format("retimed: {} durations for {} phases", durations.size(), phases.size()));
  std::vector<Knot> knots;
  double old_start = traj.startTime(), new_start = 0;
  std::size_t phase = 0;
  for (std::size_t k = 0; k < traj.knots().size(); ++k) {
    Knot knot = traj.knots()[k];
    if (k > 0 && knot.phase != traj.knots()[k - 1].phase) {  // the next phase starts here
      old_start = knot.t;  // the switch time itself: no sums, so no rounding between phases
      new_start += durations[phase];
      ++phase;
    }
    if (!(durations[phase] > 0))
      throw std::invalid_argument(fmt::format("retimed: duration {} <= 0", durations[phase]));
    const double old_duration = phases[phase].second;
    const double c = durations[phase] / old_duration;
    // Through the phase fraction, so a phase's last knot lands exactly on its new end.
    knot.t = new_start + durations[phase] * ((knot.t - old_start) / old_duration);
    knot.dtheta /= c;
    knot.ddtheta /= c * c;
    knots.push_back(std::move(knot));
  }
  return Trajectory(traj.robot(), step_length, std::move(knots));
}

}  // namespace gaitopt::gaits
