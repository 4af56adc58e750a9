#pragma once
/// @file clearance_profile.hpp
/// The least swing-tip height over the single support as a function of the phase fraction
/// s = t / T_SSP in [0, 1]: zero at lift-off and touchdown, where the tip is on the ground,
/// positive in between, so the bound at the collocation points keeps the tip off the ground
/// between them too. Both shapes are flat at s = 0 and 1: a profile with a slope there (a
/// parabola, sin(pi s)) would force a touchdown at speed >= |h'(1)| / T, which the default
/// problem's impactless optimum can only dodge between the last two points, by braking harder
/// as the mesh is refined (cost 135 -> 283 over four refinement rounds).
#include <cmath>
#include <numbers>

namespace gaitopt::ocp {

struct ClearanceProfile {
  enum class Shape { kSineSquared, kQuartic };
  bool enabled = false;  ///< false: no clearance rows at all
  double peak = 0;       ///< h at mid-swing (s = 1/2) [m]
  Shape shape = Shape::kSineSquared;

  /// h(s) [m]: peak sin^2(pi s) or peak 16 s^2 (1 - s)^2; 0 outside [0, 1].
  double at(double s) const {
    if (s <= 0 || s >= 1) return 0;
    if (shape == Shape::kQuartic) return peak * 16 * s * s * (1 - s) * (1 - s);
    const double sine = std::sin(std::numbers::pi * s);
    return peak * sine * sine;
  }
};

}  // namespace gaitopt::ocp
