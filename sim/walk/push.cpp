#include "sim/walk/push.hpp"

namespace gaitopt::sim {

double pushStart(const Push& push, double ssp_duration) {
  return push.time.value_or(0.5 * ssp_duration);
}

Vec2d pushForce(const std::optional<Push>& push, int step_index, double t, double ssp_duration) {
  if (!push || push->step != step_index + 1) return Vec2d::Zero();
  const double start = pushStart(*push, ssp_duration);
  if (t < start || t >= start + push->duration) return Vec2d::Zero();
  return push->impulse / push->duration;
}

}  // namespace gaitopt::sim
