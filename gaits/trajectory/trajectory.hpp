#pragma once
/// @file trajectory.hpp
/// The one exchange type between the polynomial gait, the optimiser, the simulator, export and
/// plots (docs/design.md#architecture): one step sampled on a time grid, with phase labels.
///
/// Knots are sorted by time. A phase switch (SSP -> DSP at touchdown) is stored as two knots at
/// the same time, the last SSP knot and the first DSP knot, because rates, accelerations and
/// forces may jump there. Evaluation at a switch time is right-continuous (returns the DSP knot),
/// except at the final time of the step. The exported files instead put the step on one
/// fixed-rate grid with strictly increasing time and keep the switch pairs and the last knot
/// beside it (grid_export.hpp); their reader rebuilds this form.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "dynamics/conventions.hpp"

namespace gaitopt::gaits {

/// Grid points this close to the end of the step or to a phase switch are on it (a rate that
/// divides the duration up to rounding gives no sliver sample; the exported switch sample stands
/// for the instant) [s].
inline constexpr double kTimeTolerance = 1e-9;

enum class Phase { kSsp, kDsp };
const char* toString(Phase phase);
/// @throws std::invalid_argument for anything but "SSP" or "DSP".
Phase phaseFromString(const std::string& text);

/// One instant of the step. Angles in the absolute convention of dynamics/conventions.hpp.
struct Knot {
  double t = 0;  ///< time since the start of the step [s]
  Phase phase = Phase::kSsp;
  Eigen::VectorXd theta;    ///< absolute angles [rad] (n)
  Eigen::VectorXd dtheta;   ///< [rad/s] (n)
  Eigen::VectorXd ddtheta;  ///< [rad/s^2] (n)
  Eigen::VectorXd tau;      ///< joint torques, q-space: tau0 stance ankle, ... [N m] (n)
  Eigen::Vector2d force_stance = Eigen::Vector2d::Zero();  ///< ground force on the robot at B [N]
  Eigen::Vector2d force_swing = Eigen::Vector2d::Zero();   ///< at E, zero in SSP [N]
};

class Trajectory {
 public:
  Trajectory() = default;
  /// @throws std::invalid_argument when knots are unsorted, sizes differ, values are not finite,
  ///         or a same-time pair is not an SSP -> DSP switch.
  Trajectory(std::string robot, double step_length, std::vector<Knot> knots);

  const std::string& robot() const { return robot_; }
  /// Distance between the tips at touchdown [m] (docs/design.md#conventions).
  double stepLength() const { return step_length_; }
  const std::vector<Knot>& knots() const { return knots_; }
  int nLinks() const;
  double startTime() const;
  double endTime() const;
  double duration() const { return endTime() - startTime(); }
  /// Duration of each phase, in order of appearance: e.g. {SSP 0.6, DSP 0.1}.
  std::vector<std::pair<Phase, double>> phaseDurations() const;

  /// The state at time t, interpolated within a phase with the highest order the knots allow:
  /// theta by quintic Hermite (theta, dtheta, ddtheta at both ends), dtheta by the derivative of
  /// that quintic, ddtheta by its second derivative; tau and forces piecewise linear.
  /// @throws std::out_of_range outside [startTime(), endTime()].
  Knot at(double t) const;

  /// Samples at a fixed rate [Hz] from the start to the end of the step, keeping both knots of
  /// every phase switch.
  Trajectory resample(double rate_hz) const;

 private:
  std::string robot_;
  double step_length_ = 0;
  std::vector<Knot> knots_;
};

}  // namespace gaitopt::gaits
