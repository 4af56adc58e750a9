#include "library/point_problem.hpp"

#include "library/library_config.hpp"

namespace gaitopt::library {
namespace {

ocp::OcpConfig scaledConfig(ocp::OcpConfig c, const std::array<double, kWalkAxes>& values) {
  const std::array<double, kWalkAxes> base = basePoint(c);
  const double time_scale =
      (values[kStepLength] / values[kSpeed]) / (base[kStepLength] / base[kSpeed]);
  for (auto& phase : c.phases) {
    phase.duration *= time_scale;
    phase.duration_min *= time_scale;
    phase.duration_max *= time_scale;
  }
  c.step_duration *= time_scale;
  c.step_length = values[kStepLength];
  c.slope = values[kSlope];
  return c;
}

/// The guess gait at the new step: lengths scale with L, speeds with v, durations follow the
/// problem's phases.
gaits::GaitParams scaledGuess(gaits::GaitParams g, const ocp::OcpConfig& point) {
  const double length_scale = point.step_length / g.step_length;
  const double speed_scale = basePoint(point)[kSpeed] / g.speed();
  g.step_length = point.step_length;
  g.ssp_duration = point.phases.front().duration;
  if (point.phases.size() > 1) g.dsp_duration = point.phases.back().duration;
  g.apex_x *= length_scale;
  g.hip_start *= length_scale;
  if (g.hip_dsp_start) *g.hip_dsp_start *= length_scale;
  if (g.hip_velocity_start) *g.hip_velocity_start *= speed_scale;
  if (g.hip_velocity_touchdown) *g.hip_velocity_touchdown *= speed_scale;
  g.slope = point.slope;
  return g;
}

}  // namespace

PointProblem pointProblem(const ocp::OcpConfig& base, const std::array<double, kWalkAxes>& values) {
  ocp::OcpConfig config = scaledConfig(base, values);
  gaits::GaitParams guess = scaledGuess(gaits::loadGait(base.guess_gait_path), config);
  dynamics::Model model = ocp::problemModel(config);
  ocp::requireReachable(model, config, "library point");
  return {std::move(config), std::move(guess), std::move(model)};
}

std::vector<double> phaseDurations(const ocp::OcpConfig& config) {
  std::vector<double> d;
  for (const auto& phase : config.phases) d.push_back(phase.duration);
  return d;
}

}  // namespace gaitopt::library
