#pragma once
/// @file poincare.hpp
/// Stability of the closed-loop walking cycle by its Poincare return map (Hurmuzlu, Genot,
/// Brogliato 2001): P maps the state at a section to the state one step later. A fixed point
/// x* = P(x*) is a periodic gait; it is locally stable when every eigenvalue (multiplier) of
/// dP/dx at x* lies inside the unit circle. The fixed point is found by iterating P (the closed
/// loop contracts towards it) and the Jacobian by central differences.
///
/// The section is the step clock at `section_clock` in single support, by default mid single
/// support. Not touchdown: a gait designed to land at rest (Mu ch. 3) sets its swing tip down
/// tangentially, so the surface "swing tip on the ground" is grazed by the flow rather than
/// crossed, and a state taken there moves as the square root of a height error; a fixed clock
/// value is crossed at rate 1 by every trajectory. The state there is (theta, dtheta, memory):
/// the controller's memory (controller.hpp) is not reset at the section, and the section must be
/// past the fade of the step's start (reference.hpp), so nothing else of the past steers the
/// robot. Section clock 0 is the step's start after relabelling, where the memory is zero and not
/// part of the state. Multipliers do not depend on the section (the maps at two sections are
/// P1 P2 and P2 P1, which share their non-zero eigenvalues; the state at the step start lacks
/// the memory, so the mid-stance map has that many more, zero, multipliers): RABBIT under HZD,
/// which strikes transversally, gives 0.5497 at the step start and 0.5496 at mid stance
/// (tests/sim/hzd_test.cpp). Measured on the optimal five-link gait under computed torque
/// (--cop-limit fail), with the difference step h = 1e-4 .. 1e-7: at the step start the largest
/// multiplier drifts 3.5e-3, 3.3e-3, 3.0e-4, 1.5e-5 (the differences do not converge); at mid
/// single support it stays 3.8e-3, 3.7e-3, 3.5e-3, 3.9e-3, and the GSN 0.01666 .. 0.01669 at both.
///
/// Beside A = dP/dx, the same differences give the linearised response to a push (the
/// stability sweeps' pulse, 0.1 s on the hip from mid single support of the step after the
/// section: B = dP/d(impulse)) and of two gait indicators of that step, its duration and its
/// advance (C and D), for the gait sensitivity norm (gait_sensitivity.hpp).
#include <limits>
#include <string>

#include <Eigen/Core>

#include "sim/studies/gait_sensitivity.hpp"
#include "sim/walk/hybrid_walk.hpp"

namespace gaitopt::sim {

struct PoincareOptions {
  int settle_steps = 15;       ///< iterations of P towards the fixed point
  double perturbation = 1e-6;  ///< central-difference step [rad, rad/s, memory units, N s]
  /// The section's step clock [s]: NaN for mid single support (half the reference's), 0 for the
  /// step's start; else at least the reference's fadeTime() and before its touchdown.
  double section_clock = std::numeric_limits<double>::quiet_NaN();
  EventIntegratorOptions integrator;
  ContactRules rules;  ///< the walk's own (a map under other rules is of another cycle)
};

struct PoincareAnalysis {
  bool ok = false;
  std::string failure;              ///< a step that failed while settling or differencing
  double section_clock = 0;         ///< the section used [s]
  Eigen::VectorXd fixed_point;      ///< (theta, dtheta, memory) at the section
  double fixed_point_residual = 0;  ///< |P(x*) - x*|_inf
  Eigen::MatrixXd jacobian;         ///< A = dP/dx
  Eigen::VectorXcd multipliers;
  double max_multiplier = 0;  ///< largest |eigenvalue|
  /// A, B (per N s of push), C, D of the indicators (step duration [s], step advance [m]).
  LinearisedGait linearised;
  /// GSN of a push (Hobbelen and Wisse 2007) on the two indicators; NaN when not stable.
  double gait_sensitivity_norm = std::numeric_limits<double>::quiet_NaN();
  Eigen::Vector2d gait_sensitivity_per_indicator = Eigen::Vector2d::Constant(
      std::numeric_limits<double>::quiet_NaN());  ///< step duration [s/(N s)], advance [m/(N s)]
};

PoincareAnalysis analysePoincare(const dynamics::Model& plant, const Controller& controller,
                                 const Reference& ref, const PoincareOptions& options = {});

}  // namespace gaitopt::sim
