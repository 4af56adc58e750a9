#pragma once
/// @file model_variation.hpp
/// Variants of a Model for robustness studies: the parameter uncertainty of Mu (2004) ch. 4
/// (phi_hat = (1 + E) phi for phi in {m, I, l, d}, sec. 4.3 cases 1-3) and a different ground
/// friction. Used on the simulated plant only, so the controller keeps its nominal model.
#include "dynamics/model.hpp"

namespace gaitopt::dynamics {

/// Relative errors E of every link's parameters (0.4 = +40 %), each > -1.
struct ParameterErrors {
  double mass = 0;     ///< e_m on m_i
  double inertia = 0;  ///< e_I on I_i
  double length = 0;   ///< e_l on l_i
  double com = 0;      ///< e_d on d_i (the CoM offset)
};

/// Mu's uncertainty case 1 (none), 2 (e_m = e_I = 40 %, e_l = e_d = 10 %) or 3 (100 %, 40 %).
/// @throws std::invalid_argument for another case number.
ParameterErrors muUncertaintyCase(int mu_case);

/// The model with every link's parameters scaled by (1 + E); joints, feet, gravity, friction,
/// slope unchanged. @throws std::invalid_argument when an error is <= -1 or not finite.
Model perturbedModel(const Model& nominal, const ParameterErrors& errors);

/// The model on a ground of Coulomb coefficient `friction` (>= 0); slope unchanged.
Model withFriction(const Model& nominal, double friction);

/// The model with other feet (heel, toe >= 0 [m]); everything else unchanged.
Model withFoot(const Model& nominal, const Foot& foot);

/// The model on a ground inclined by `slope` [rad] (> 0 uphill, |slope| < pi/2): gravity rotates
/// in the ground frame (model.hpp); links, joints, feet, friction unchanged.
/// @throws std::invalid_argument when the slope is not finite or |slope| >= pi/2.
Model withSlope(const Model& nominal, double slope);

}  // namespace gaitopt::dynamics
