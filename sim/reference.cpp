#include "sim/reference.hpp"

#include <algorithm>
#include <stdexcept>

namespace gaitopt::sim {
namespace {

/// The knots of one phase, as a trajectory of its own (no switch inside).
gaits::Trajectory phasePart(const gaits::Trajectory& step, gaits::Phase phase) {
  std::vector<gaits::Knot> knots;
  for (const auto& k : step.knots())
    if (k.phase == phase) knots.push_back(k);
  return gaits::Trajectory(step.robot(), step.stepLength(), std::move(knots));
}

}  // namespace

Reference::Reference(const gaits::Trajectory& step) {
  if (step.knots().empty() || step.knots().front().phase != gaits::Phase::kSsp)
    throw std::invalid_argument("a reference step starts with single support");
  ssp_ = phasePart(step, gaits::Phase::kSsp);
  ssp_end_ = ssp_.endTime();
  end_ = step.endTime();
  const auto dsp_count = std::count_if(step.knots().begin(), step.knots().end(),
                                       [](const auto& k) { return k.phase == gaits::Phase::kDsp; });
  if (dsp_count >= 2) dsp_ = phasePart(step, gaits::Phase::kDsp);
}

gaits::Knot Reference::at(gaits::Phase phase, double t) const {
  const gaits::Trajectory& part = phase == gaits::Phase::kDsp && dsp_ ? *dsp_ : ssp_;
  gaits::Knot k = part.at(std::clamp(t, part.startTime(), part.endTime()));
  k.t = t;
  return k;
}

}  // namespace gaitopt::sim
