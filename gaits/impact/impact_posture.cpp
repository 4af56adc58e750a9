#include "gaits/impact/impact_posture.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include <fmt/format.h>
#include <Eigen/LU>

#include "dynamics/kinematics.hpp"
#include "gaits/polynomial/leg_ik.hpp"

namespace gaitopt::gaits {
namespace {

void requireParams(const dynamics::Model& model, const ImpactPostureParams& p) {
  if (model.legLinks() != 2)
    throw std::invalid_argument(fmt::format(
        "the impact posture (Mu ch. 5) needs legs of two links (thigh and shank); robot '{}' "
        "has {} per leg",
        model.name(), model.legLinks()));
  // sigma = 0 is a singular point of the study (Mu sec. 5.3, after Hurmuzlu 1993); alpha = 0 or
  // pi would be a tip sliding horizontally, not an impact (ydot_e^- < 0 is required).
  if (!(p.step_length > 0 && p.knee_bias > 0 && p.knee_bias < std::numbers::pi &&
        p.approach_angle > 0 && p.approach_angle < std::numbers::pi && p.approach_speed > 0))
    throw std::invalid_argument(fmt::format(
        "impact posture needs step_length > 0, 0 < sigma < pi, 0 < alpha < pi, V_e > 0; got "
        "{} m, {} rad, {} rad, {} m/s",
        p.step_length, p.knee_bias, p.approach_angle, p.approach_speed));
}

double hipReach(const dynamics::Model& model, double knee_bias) {
  const double l1 = model.link(0).length;
  const double l2 = model.link(1).length;
  return std::sqrt(l1 * l1 + l2 * l2 + 2 * l1 * l2 * std::cos(knee_bias));
}

/// Joint rates with J dtheta = tip_velocity and least |dtheta| (J has full row rank).
VecD minimumNormRates(const dynamics::Model& model, const VecD& theta, const Vec2d& tip_velocity) {
  const Mat2Xd jac = dynamics::pointJacobian(model.tipWeights(), theta);
  return jac.transpose() * (jac * jac.transpose()).inverse() * tip_velocity;
}

}  // namespace

double maxImpactStepLength(const dynamics::Model& model, double knee_bias) {
  return 2 * hipReach(model, knee_bias);
}

double impactHipHeight(const dynamics::Model& model, const ImpactPostureParams& params) {
  requireParams(model, params);
  const double reach = hipReach(model, params.knee_bias);
  const double x_h = params.step_length / 2;  // x_h^- = S_L / 4 (Mu sec. 5.3, condition ii)
  if (!(x_h < reach))
    throw std::domain_error(fmt::format(
        "leg cannot reach: step_length {:.4f} m needs a hip reach above {:.4f} m, but knee bias "
        "{:.2f} deg gives {:.4f} m",
        params.step_length, x_h, params.knee_bias / kDeg, reach));
  return std::sqrt(reach * reach - x_h * x_h);
}

PreImpactState impactPosture(const dynamics::Model& model, const ImpactPostureParams& params) {
  const int n = model.nLinks();
  const Eigen::Vector2d hip(params.step_length / 2, impactHipHeight(model, params));
  const Eigen::Vector2d tip(params.step_length, 0);
  // Stance leg B -> hip and swing leg hip -> E, knees forward: sigma > 0 is a forward knee.
  PointMotion to_hip, to_tip;  // positions only: the rates come from Xdot_e^- below
  to_hip.pos = hip;
  to_tip.pos = tip - hip;
  const LegAngles stance = legInverseKinematics(model.link(0).length, model.link(1).length, to_hip,
                                                KneeDirection::kForward);
  const LegAngles swing = legInverseKinematics(model.link(n - 2).length, model.link(n - 1).length,
                                               to_tip, KneeDirection::kForward);
  PreImpactState state;
  state.theta = VecD::Zero(n);  // the torso entry (if any) stays 0: upright (condition i)
  state.theta.head<2>() = stance.theta;
  state.theta.tail<2>() = swing.theta;
  const double alpha = params.approach_angle;
  const Vec2d tip_velocity = -params.approach_speed * Vec2d(std::cos(alpha), std::sin(alpha));
  state.dtheta = minimumNormRates(model, state.theta, tip_velocity);
  return state;
}

}  // namespace gaitopt::gaits
