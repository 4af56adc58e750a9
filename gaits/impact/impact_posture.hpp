#pragma once
/// @file impact_posture.hpp
/// The pre-impact state of Mu's (2004) contact-event study (sec. 5.3): a posture fixed by the
/// step length, the stance knee bias angle sigma and two conditions of the thesis (torso upright,
/// hip centred between the tips), and a swing-tip velocity of direction alpha and magnitude V_e.
#include "dynamics/model.hpp"

namespace gaitopt::gaits {

/// Parameters of one pre-impact state, all "measured right before impact" (Mu sec. 5.3).
struct ImpactPostureParams {
  /// tip distance at touchdown [m], Mu's S_L / 2 (docs/design.md#conventions)
  double step_length = 0;
  double knee_bias = 0;       ///< sigma = theta1^- - theta2^-, the trailing knee angle [rad]
  double approach_angle = 0;  ///< alpha = acot(xdot_e^- / ydot_e^-), from the -x axis [rad]
  double approach_speed = 1;  ///< V_e = |Xdot_e^-| [m/s]
};

/// Absolute angles and rates just before impact (dim model.nLinks()).
struct PreImpactState {
  VecD theta;
  VecD dtheta;
};

/// Builds Mu's ch. 5 pre-impact state for a robot with two-link legs:
/// - theta3^- = 0 (torso upright, sec. 5.3 condition i) when the robot has a torso;
/// - x_h^- = S_L / 4 = step_length / 2 (hip centred, condition ii) and a stance knee angle
///   theta1 - theta2 = sigma fix the hip; both knees bend forward (Mu ch. 3), so the swing leg
///   mirrors the stance leg and the swing tip E lies at (step_length, 0), cf. (2.23c);
/// - Xdot_e^- = -V_e (cos alpha, sin alpha), from alpha = acot(xdot_e / ydot_e) with ydot_e < 0
///   (sec. 5.2.1). The impulses depend on Xdot_e^- only (sec. 5.2, remark 1), so dtheta^- is
///   the Euclidean minimum-norm solution of J dtheta = Xdot_e^- (J of 2.23c).
/// @throws std::invalid_argument when the legs are not thigh + shank, or a parameter lies
///         outside step_length > 0, 0 < sigma < pi, 0 < alpha < pi, V_e > 0.
/// @throws std::domain_error when the stance leg cannot reach the hip (step too long).
PreImpactState impactPosture(const dynamics::Model& model, const ImpactPostureParams& params);

/// Hip height y_h^- of the posture [m]; the stance leg reaches the hip at distance
/// sqrt(l1^2 + l2^2 + 2 l1 l2 cos sigma) (law of cosines with interior knee angle pi - sigma).
/// @throws as impactPosture.
double impactHipHeight(const dynamics::Model& model, const ImpactPostureParams& params);

/// Longest step_length whose posture exists at knee bias sigma: twice the hip reach [m].
double maxImpactStepLength(const dynamics::Model& model, double knee_bias);

}  // namespace gaitopt::gaits
