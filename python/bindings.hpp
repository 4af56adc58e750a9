#pragma once
/// @file bindings.hpp
/// The parts of the `gaitopt` Python module, one per file, added to the module by module.cpp.
#include <stdexcept>
#include <string>

#include <pybind11/pybind11.h>

namespace gaitopt::dynamics {
class Model;
}
namespace gaitopt::gaits {
class Trajectory;
}

namespace gaitopt::python {

/// @throws std::invalid_argument (InputError) when `traj` is not a gait of `robot` (by name): its
/// motion with another robot's masses would be written or walked as this one's, unseen.
void requireTrajectoryOf(const gaits::Trajectory& traj, const dynamics::Model& robot);

/// A solve that did not succeed: InfeasibleError (exit code 3) or NotConvergedError (4).
struct SolveFailed : std::runtime_error {
  SolveFailed(const std::string& message, bool is_infeasible)
      : std::runtime_error(message), infeasible(is_infeasible) {}
  bool infeasible;
};

/// GaitoptError and its subclasses, and the translation of the C++ exceptions into them.
void bindErrors(pybind11::module_& m);
/// Robot: a model loaded from a robot YAML; D, H, G, energies, forward dynamics.
void bindRobot(pybind11::module_& m);
/// Trajectory; design_poly, read_trajectory.
void bindTrajectory(pybind11::module_& m);
/// optimize: an OCP config solved with Ipopt.
void bindSolve(pybind11::module_& m);
/// simulate: a closed-loop walk.
void bindWalk(pybind11::module_& m);

}  // namespace gaitopt::python
