#pragma once
/// @file polynomial_gait.hpp
/// The classical gait of Mu (2004) ch. 3: swing-tip path (3.1-3.12), hip path (3.13-3.23),
/// joint angles by inverse kinematics (3.24), in gaitopt's conventions: one step is SSP on
/// [0, T_S] then DSP on [T_S, T_S + T_D], all relative to the SSP stance tip B (the origin),
/// the swing tip travelling from -step_length to +step_length (Mu's -S_L/2 to S_L/2).
#include "dynamics/model.hpp"
#include "gaits/polynomial/gait_params.hpp"
#include "gaits/polynomial/leg_ik.hpp"
#include "gaits/polynomial/polynomial.hpp"
#include "gaits/trajectory/trajectory.hpp"

namespace gaitopt::gaits {

/// The free hip parameters once chosen: V_h1 (3.18-3.19), V_h2 (3.22-3.23), S_D0 (3.20-3.21).
struct HipPlan {
  double velocity_start = 0;      ///< V_h1 [m/s]
  double velocity_touchdown = 0;  ///< V_h2 [m/s]
  double dsp_start = 0;           ///< S_D0 [m]
  double start = 0;               ///< S_S0: the hip behind the stance tip at SSP start [m]
  double height = 0;              ///< H_h [m]
};

/// @throws std::invalid_argument unless every leg has two links (thigh and shank).
void requireKneedLegs(const dynamics::Model& model);

/// Joint-space kinematics at one instant.
struct GaitKinematics {
  VecD theta, dtheta, ddtheta;
};

class PolynomialGait {
 public:
  /// @throws std::invalid_argument when the robot's legs do not have two links each or the
  ///         apex cannot be reached by the swing-tip cubic.
  PolynomialGait(const dynamics::Model& model, GaitParams params, HipPlan plan);

  const GaitParams& params() const { return params_; }
  const HipPlan& plan() const { return plan_; }
  double apexTime() const { return t_m_; }             ///< T_m of (3.4-3.6) [s]
  const Polynomial& swingX() const { return x_a_; }    ///< x_a (3.1), SSP time
  const Polynomial& swingY() const { return y_a_; }    ///< y_a (3.1), SSP time
  const Polynomial& hipXSsp() const { return x_hs_; }  ///< x_hS (3.13a), SSP time
  const Polynomial& hipXDsp() const { return x_hd_; }  ///< x_hD (3.13c), DSP local time

  /// Swing tip relative to B at step time t (fixed at (step_length, 0) in the DSP).
  PointMotion swingTip(double t, Phase phase) const;
  /// Hip relative to B at step time t.
  PointMotion hip(double t, Phase phase) const;
  /// Joint angles, rates and accelerations by (3.24) at step time t.
  /// @throws std::domain_error when a leg cannot reach (names the time and phase).
  GaitKinematics kinematics(double t, Phase phase) const;
  /// Whether kinematics(t, phase) finds both legs within reach, without solving for the angles.
  bool reachable(double t, Phase phase) const;

 private:
  const dynamics::Model* model_;
  GaitParams params_;
  HipPlan plan_;
  double t_m_ = 0;
  Polynomial x_a_, y_a_, x_hs_, x_hd_;
};

/// Samples the gait at `rate_hz` (plus both knots of the touchdown switch) with inverse
/// dynamics: SSP torques by (2.7, 2.43); DSP torques and tip forces by distributeDspForces.
Trajectory buildTrajectory(const PolynomialGait& gait, const dynamics::Model& model,
                           double rate_hz);

}  // namespace gaitopt::gaits
