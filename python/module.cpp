/// @file module.cpp
/// `import gaitopt` (build/python on PYTHONPATH): the toolkit from Python.
#include "python/bindings.hpp"

PYBIND11_MODULE(gaitopt, m) {
  m.doc() =
      "gaitopt: planar biped dynamics, polynomial gaits, gait optimisation (Ipopt) and "
      "closed-loop walks. Arrays are numpy arrays in SI units; angles follow "
      "dynamics/conventions.hpp (absolute, from the upward vertical, clockwise positive).";
  gaitopt::python::bindErrors(m);
  gaitopt::python::bindRobot(m);
  gaitopt::python::bindTrajectory(m);
  gaitopt::python::bindSolve(m);
  gaitopt::python::bindWalk(m);
}
