#pragma once
/// @file export_contract.hpp
/// What a dense export (trajectory.csv) promises a controller between the solver's points, as
/// bounds on the figures of export_checks.hpp and metrics.hpp. A solver holds its constraints at
/// its collocation points only; the export reads the scheme's polynomials in between, where a
/// force can dip, a tip can drift and an interpolant can disagree with its derivative
/// (docs/optimal_gaits.md#between-the-points). The first three bounds are issue 34's on the
/// 1 kHz export; then the contact conditions themselves (the robot's own mu, the foot's own
/// length, the ground), without the design margins a config may add at its points; and the
/// robot file's joint velocity and torque limits, which an actuator cannot pass whatever a
/// config bounds.
#include <string>
#include <vector>

#include "dynamics/model.hpp"
#include "gaits/trajectory/trajectory.hpp"

namespace gaitopt::gaits {

inline constexpr double kMaxDspTipDrift = 1e-6;           ///< [m]
inline constexpr double kMaxRateMismatch = 2e-3;          ///< of the rates' peak
inline constexpr double kMaxAccelerationMismatch = 1e-2;  ///< of the accelerations' peak
/// How far a joint's rate or torque may pass the robot file's limit before it counts: 1 %. A
/// bound the solver holds at its points is passed between them by the interpolant's curvature
/// (the default problem with constraints.joint_velocity_limits: 0.09 %), which no actuator
/// rating is exact to.
inline constexpr double kLimitTolerance = 0.01;
/// [m] how far below the ground the swing tip, or beyond the foot's ends its centre of
/// pressure, may pass before it counts: a micrometre, the drift's bound.
inline constexpr double kGroundTolerance = 1e-6;
/// The derivative checks compare with three-point differences, which themselves err by
/// O(h^2) (export_checks.hpp): the default optimum's export shows 2.2 % and 3.3 % at 200 Hz
/// (results/sample_opt_mu2004_200hz/summary.json) where it shows 0.12 % and 0.37 % at 1 kHz.
/// They are checked on exports at this rate or finer.
inline constexpr double kDerivativeCheckRateHz = 1000;

struct ExportBreach {
  std::string check;  ///< the figure's key under summary.json's between_nodes
  double value = 0;
  double bound = 0;
  std::string meaning;  ///< what it means for a controller that follows the export
};

/// The figures of a dense export the contract bounds, each computed once: summary.json writes
/// them under between_nodes by these names, and exportBreaches judges the same numbers.
struct ExportFigures {
  double max_dsp_tip_drift = 0;          ///< [m] maxDspTipDrift
  double max_rate_mismatch = 0;          ///< maxRateMismatch
  double max_acceleration_mismatch = 0;  ///< maxAccelerationMismatch
  double min_normal_force = 0;           ///< [N] minNormalForce
  double max_friction_ratio = 0;         ///< maxFrictionRatio
  double min_foot_cop_margin = 0;        ///< [m] minFootCopMargin
  double min_swing_clearance = 0;        ///< [m] minSwingClearance
  double max_joint_rate_use = 0;         ///< maxJointRateUse
  double max_torque_use = 0;             ///< maxTorqueUse
};

ExportFigures exportFigures(const Trajectory& dense, const dynamics::Model& model);

/// The bounds an export with these figures, sampled at `rate_hz`, breaks (none: it keeps every
/// one); `friction` is the robot's mu. Friction and the foot's centre of pressure are not judged
/// where a normal force is <= 0 (that breach is reported instead).
std::vector<ExportBreach> exportBreaches(const ExportFigures& figures, double friction,
                                         double rate_hz);

/// The checks exportBreaches leaves unjudged on an export sampled at `rate_hz`: the derivative
/// checks below kDerivativeCheckRateHz, whose differences would err by more than their bounds.
/// summary.json names them, so that no breach listed does not read as "checked and kept".
std::vector<std::string> unjudgedChecks(double rate_hz);

}  // namespace gaitopt::gaits
