#pragma once
/// @file controller.hpp
/// What every closed-loop walk (hybrid_walk.hpp, compliant_walk.hpp, lcp_walk.hpp) asks of a
/// controller: joint torques at the measured state. Tracking controllers follow the reference
/// knot of the step clock (tracking_controller.hpp); a state-feedback law such as HZD
/// (hzd_controller.hpp) may ignore it. A controller with memory (the integral of Mu's sliding
/// surface, 4.1) names how many states it keeps in a phase; the walk integrates them beside the
/// plant's state. Every walk starts them at a phase start from phaseStartMemory, which at the
/// switch from single to double support also sees the end of the single support
/// (PhaseHandover); the rigid walk starts a step's single support from zero.
#include <Eigen/Core>

#include "dynamics/conventions.hpp"
#include "gaits/trajectory/trajectory.hpp"

namespace gaitopt::sim {

/// The end of the phase before a switch: the last state, reference knot and memory the
/// controller saw in it.
struct PhaseHandover {
  gaits::Phase phase = gaits::Phase::kSsp;
  VecD theta, dtheta;
  gaits::Knot ref;
  Eigen::VectorXd memory;
};

/// Joint torques and memory rate at one state (Controller::control).
struct ControlOutput {
  VecD tau;
  Eigen::VectorXd memory_rate;
};

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
  /// (size memorySize(phase)); `previous` is the end of the phase before, or null at a step's
  /// start. Zero unless the controller says otherwise.
  virtual Eigen::VectorXd phaseStartMemory(gaits::Phase phase, const VecD& /*theta*/,
                                           const VecD& /*dtheta*/, const gaits::Knot& /*ref*/,
                                           const PhaseHandover* /*previous*/) const {
    return Eigen::VectorXd::Zero(memorySize(phase));
  }
  /// d(memory)/dt at the same arguments (size memorySize(phase)).
  virtual Eigen::VectorXd memoryRate(gaits::Phase /*phase*/, const VecD& /*theta*/,
                                     const VecD& /*dtheta*/, const gaits::Knot& /*ref*/,
                                     const Eigen::VectorXd& /*memory*/) const {
    return {};
  }
  /// torque() and memoryRate() at the same arguments, in one call: a controller whose memory
  /// follows terms of its torque law (Mu's T_c filter) computes them once.
  virtual ControlOutput control(gaits::Phase phase, const VecD& theta, const VecD& dtheta,
                                const gaits::Knot& ref, const Eigen::VectorXd& memory) const {
    return {torque(phase, theta, dtheta, ref, memory),
            memoryRate(phase, theta, dtheta, ref, memory)};
  }
};

}  // namespace gaitopt::sim
