#pragma once
/// @file controller.hpp
/// What every closed-loop walk (hybrid_walk.hpp, compliant_walk.hpp, lcp_walk.hpp) asks of a
/// controller: joint torques at the measured state. Tracking controllers follow the reference
/// knot of the step clock (tracking_controller.hpp); a state-feedback law such as HZD
/// (hzd_controller.hpp) may ignore it.
#include "dynamics/conventions.hpp"
#include "gaits/trajectory.hpp"

namespace gaitopt::sim {

class Controller {
 public:
  virtual ~Controller() = default;
  /// Joint torques (q-space, tau0 the stance ankle) at (theta, dtheta), within the torque
  /// limits, for the reference knot `ref` of the step clock [N m].
  virtual VecD torque(gaits::Phase phase, const VecD& theta, const VecD& dtheta,
                      const gaits::Knot& ref) const = 0;
};

}  // namespace gaitopt::sim
