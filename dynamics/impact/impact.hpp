#pragma once
/// @file impact.hpp
/// Rigid, perfectly plastic impact of the swing tip E with the ground (Mu 2004 sec. 2.3.3 and
/// ch. 5, after Hurmuzlu 1993). Labels are the pre-impact ones: B is the old stance (trailing)
/// tip, E the colliding (leading) tip. Impulses are exerted by the ground on the robot.
/// The configuration does not change; joint torques stay finite (no impulsive actuation).
#include "dynamics/model.hpp"

namespace gaitopt::dynamics {

struct ImpactResult {
  VecD dtheta_plus;            ///< post-impact absolute rates [rad/s]
  Vec2d impulse_trailing;      ///< impulse at B [N s] (P_l; zero for a single impact)
  Vec2d impulse_leading;       ///< impulse at E [N s] (P_r, or P_S for a single impact)
  Vec2d trailing_velocity;     ///< velocity of B after impact [m/s] (zero for a double impact)
  bool unilateral_ok = false;  ///< double: P_ly > 0 (2.31a); single: ydot_b+ > 0 (2.37a)
  bool friction_ok = false;    ///< |P_x| < mu |P_y| at every tip with an impulse (2.31b-c, 2.37b)
};

/// Double impact (Mu 2.23-2.30): both tips stay on the ground with zero velocity.
/// P_l = (J W^-1 J^T)^-1 J dtheta^- (2.27), dtheta^+ = dtheta^- - W^-1 J^T P_l (2.28),
/// P_r = V (dtheta^+ - dtheta^-) - P_l (2.29a).
ImpactResult doubleImpact(const Model& model, const VecD& theta, const VecD& dtheta_minus);

/// Single impact (Mu 2.32-2.36): B is free (Xdot_b^- = 0) and lifts off, E stops.
/// (W - U J) ddelta = U Xdot_e^- (2.34a) with W - U J formed by matrix product (the closed form
/// 2.34b is misprinted) and U from (2.32b) with d_i in place of the printed d_j.
ImpactResult singleImpact(const Model& model, const VecD& theta, const VecD& dtheta_minus);

/// Mu's refined criterion (sec. 5.3): which impact the pre-impact state admits.
enum class ImpactType { kDouble, kSingle, kEither, kNeither };
ImpactType classifyImpact(const Model& model, const VecD& theta, const VecD& dtheta_minus);
const char* toString(ImpactType type);

/// W of Mu (2.23b): lower triangular, n x n.
MatD impactW(const Model& model, const VecD& theta);
/// U of Mu (2.32b) with the d_i correction: n x 2.
Eigen::Matrix<double, Eigen::Dynamic, 2, 0, kMaxLinks, 2> impactU(const Model& model,
                                                                  const VecD& theta);

}  // namespace gaitopt::dynamics
