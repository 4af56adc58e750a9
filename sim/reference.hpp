#pragma once
/// @file reference.hpp
/// An exported gait (trajectory CSV, DESIGN.md sec. 5) as the reference a controller tracks:
/// one step, SSP then optionally DSP, read on the step clock. The clock restarts at every SSP
/// start and jumps to the reference touchdown time at the actual touchdown, so a step that
/// lands early or late is compared with the right phase of the reference.
#include <optional>

#include "gaits/trajectory.hpp"

namespace gaitopt::sim {

class Reference {
 public:
  /// @throws std::invalid_argument when the trajectory does not start with an SSP.
  explicit Reference(const gaits::Trajectory& step);

  /// The reference knot of `phase` at step clock t, held at the phase's ends outside them.
  gaits::Knot at(gaits::Phase phase, double t) const;
  double touchdownTime() const { return ssp_end_; }  ///< SSP duration [s]
  double endTime() const { return end_; }            ///< step duration [s]
  bool hasDsp() const { return dsp_.has_value(); }
  double stepLength() const { return ssp_.stepLength(); }
  /// The state the step starts from.
  const gaits::Knot& start() const { return ssp_.knots().front(); }

 private:
  gaits::Trajectory ssp_;
  std::optional<gaits::Trajectory> dsp_;
  double ssp_end_ = 0, end_ = 0;
};

}  // namespace gaitopt::sim
