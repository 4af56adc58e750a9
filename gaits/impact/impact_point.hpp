#pragma once
/// @file impact_point.hpp
/// One point of Mu's (2004) contact-event study (sec. 5.2-5.3): the pre-impact state of
/// impact_posture.hpp, both impact models, the refined classification and the impulse ratios.
#include "dynamics/impact/frictional_impact.hpp"
#include "dynamics/impact/impact.hpp"
#include "gaits/impact/impact_posture.hpp"

namespace gaitopt::gaits {

struct ImpactPoint {
  ImpactPostureParams params;
  double hip_height = 0;        ///< y_h^- of the posture [m]
  dynamics::ImpactType type{};  ///< refined criterion of sec. 5.3 (classifyImpact)
  /// What the complementarity law over both tips with Coulomb friction and a plastic impact
  /// allows (dynamics::complementarityImpact): the families among its solutions.
  dynamics::ImpactType lcp_type{};
  dynamics::ImpactResult double_model;  ///< (2.30): P_l at B, P_r at E
  dynamics::ImpactResult single_model;  ///< (2.36): Xdot_b^+, P_S at E
  double mu_l = 0;  ///< P_lx / P_ly, trailing tip in a double impact (sec. 5.3.3)
  double mu_r = 0;  ///< P_rx / P_ry, leading tip in a double impact
  double mu_s = 0;  ///< P_Sx / P_Sy, colliding tip in a single impact
};

/// Signed impulse ratio P_x / P_y of Mu sec. 5.3.3; a tip slips unless |ratio| < mu
/// (2.31b-c, 2.37b). +-inf or NaN when P_y = 0.
inline double impulseRatio(const Vec2d& impulse) {
  return impulse(0) / impulse(1);
}

/// Evaluates both impact models at the pre-impact state of `params`.
/// @throws as impactPosture.
ImpactPoint evaluateImpactPoint(const dynamics::Model& model, const ImpactPostureParams& params);

}  // namespace gaitopt::gaits
