#pragma once
/// @file dsp_force_distribution.hpp
/// Inverse dynamics of the double support, which is over-actuated: n joint torques and two tip
/// forces for n - 2 degrees of freedom (Mu 2.11, 2.21). The motion fixes the total ground force
/// and the ZMP; how the load is shared between the tips is a choice. We take the physically
/// sensible one of least effort: the tip force lambda at E that minimises ||tau||^2, where
///   tau(lambda) = M^-T (D ddtheta + N - J^T lambda)          (2.11, 2.43)
///   F_B = m (a_com + g e_y) - lambda                          (total linear momentum)
/// subject to unilateral contact (F_By >= 0, F_Ey >= 0), Coulomb friction at both tips
/// (|F_x| <= mu F_y, mu from the robot) and tau0 = 0 when the stance ankle is unactuated.
/// Solved with NLopt's SLSQP (a 2-variable QP with linear constraints; exact gradients).
#include "dynamics/model.hpp"

namespace gaitopt::gaits {

struct DspForces {
  VecD tau;               ///< joint torques [N m]
  Vec2d force_stance;     ///< ground force on the robot at B [N]
  Vec2d force_swing;      ///< ground force on the robot at E [N]
  bool feasible = false;  ///< every constraint holds (to 1e-9 N); false: least-norm fallback
};

DspForces distributeDspForces(const dynamics::Model& model, const VecD& theta, const VecD& dtheta,
                              const VecD& ddtheta);

}  // namespace gaitopt::gaits
