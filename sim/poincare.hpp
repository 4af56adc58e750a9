#pragma once
/// @file poincare.hpp
/// Stability of the closed-loop walking cycle by its Poincare return map (Hurmuzlu et al.,
/// seed 001): the section is the start of single support, right after relabelling; P maps the
/// state (theta, dtheta) there to the state one step later. A fixed point x* = P(x*) is a
/// periodic gait; it is locally stable when every eigenvalue (multiplier) of dP/dx at x* lies
/// inside the unit circle. The fixed point is found by iterating P (the closed loop contracts
/// towards it) and the Jacobian by central differences.
#include <string>

#include <Eigen/Core>

#include "sim/hybrid_walk.hpp"

namespace gaitopt::sim {

struct PoincareOptions {
  int settle_steps = 15;       ///< iterations of P towards the fixed point
  double perturbation = 1e-6;  ///< central-difference step [rad, rad/s]
  EventIntegratorOptions integrator;
  ContactRules rules;  ///< the walk's own (a map under other rules is of another cycle)
};

struct PoincareAnalysis {
  bool ok = false;
  std::string failure;              ///< a step that failed while settling or differencing
  Eigen::VectorXd fixed_point;      ///< (theta, dtheta) at the section
  double fixed_point_residual = 0;  ///< |P(x*) - x*|_inf
  Eigen::MatrixXd jacobian;
  Eigen::VectorXcd multipliers;
  double max_multiplier = 0;  ///< largest |eigenvalue|
};

PoincareAnalysis analysePoincare(const dynamics::Model& plant, const Controller& controller,
                                 const Reference& ref, const PoincareOptions& options = {});

}  // namespace gaitopt::sim
