#pragma once
/// @file controller.hpp
/// What every closed-loop walk (hybrid_walk.hpp, compliant_walk.hpp, lcp_walk.hpp) asks of a
/// controller: joint torques at the measured state. Tracking controllers follow the reference
/// knot of the step clock (tracking_controller.hpp); a state-feedback law such as HZD
/// (hzd_controller.hpp) may ignore it. A controller with memory (the integral of Mu's sliding
/// surface, 4.1) names how many states it keeps in a phase; the walk integrates them beside the
/// plant's state. The rigid walk starts them from zero at every phase start; the free-base walk
/// (free_base_walk.hpp) from phaseStartMemory.
#include <Eigen/Core>

#include "dynamics/conventions.hpp"
#include "gaits/trajectory.hpp"

namespace gaitopt::sim {

class Controller {
 public:
  virtual ~Controller() = default;
  /// Joint torques (q-space, tau0 the stance ankle) at (theta, dtheta), within the torque
  /// limits, for the reference knot `ref` of the step clock [N m]; memory of memorySize(phase).
  virtual VecD torque(gaits::Phase phase, const VecD& theta, const VecD& dtheta,
                      const gaits::Knot& ref, const Eigen::VectorXd& memory) const = 0;
  /// How many states the controller integrates in `phase` (0: none).
  virtual int memorySize(gaits::Phase /*phase*/) const { return 0; }
  /// The memory a phase starts with at (theta, dtheta) and the phase's first reference knot
  /// (size memorySize(phase)); zero unless the controller says otherwise.
  virtual Eigen::VectorXd phaseStartMemory(gaits::Phase phase, const VecD& /*theta*/,
                                           const VecD& /*dtheta*/,
                                           const gaits::Knot& /*ref*/) const {
    return Eigen::VectorXd::Zero(memorySize(phase));
  }
  /// d(memory)/dt at the same arguments (size memorySize(phase)).
  virtual Eigen::VectorXd memoryRate(gaits::Phase /*phase*/, const VecD& /*theta*/,
                                     const VecD& /*dtheta*/, const gaits::Knot& /*ref*/,
                                     const Eigen::VectorXd& /*memory*/) const {
    return {};
  }
};

}  // namespace gaitopt::sim
