#include "gaits/export/export_contract.hpp"

#include <utility>

#include "gaits/export/export_checks.hpp"
#include "gaits/export/metrics.hpp"

namespace gaitopt::gaits {
namespace {

/// Collects breaches: an upper bound broken when value > bound, a lower one when value < bound.
class Breaches {
 public:
  void atMost(const char* check, double value, double bound, const char* meaning) {
    if (value > bound) list_.push_back({check, value, bound, meaning});
  }
  void atLeast(const char* check, double value, double bound, const char* meaning) {
    if (value < bound) list_.push_back({check, value, bound, meaning});
  }
  std::vector<ExportBreach> take() { return std::move(list_); }

 private:
  std::vector<ExportBreach> list_;
};

}  // namespace

ExportFigures exportFigures(const Trajectory& dense, const dynamics::Model& model) {
  return {.max_dsp_tip_drift = maxDspTipDrift(dense, model),
          .max_rate_mismatch = maxRateMismatch(dense),
          .max_acceleration_mismatch = maxAccelerationMismatch(dense),
          .min_normal_force = minNormalForce(dense),
          .max_friction_ratio = maxFrictionRatio(dense),
          .min_foot_cop_margin = minFootCopMargin(dense, model),
          .min_swing_clearance = minSwingClearance(dense, model),
          .max_joint_rate_use = maxJointRateUse(dense, model),
          .max_torque_use = maxTorqueUse(dense, model)};
}

std::vector<ExportBreach> exportBreaches(const ExportFigures& f, double friction, double rate_hz) {
  Breaches b;
  b.atMost("max_dsp_tip_drift", f.max_dsp_tip_drift, kMaxDspTipDrift,
           "the double support's leading tip leaves the place it is pinned to (the DSP in "
           "reduced coordinates holds it: constraints.dsp_reduced_coordinates)");
  if (unjudgedChecks(rate_hz).empty()) {
    b.atMost("max_rate_mismatch", f.max_rate_mismatch, kMaxRateMismatch,
             "the rates are not the derivatives of the angles");
    b.atMost("max_acceleration_mismatch", f.max_acceleration_mismatch, kMaxAccelerationMismatch,
             "the accelerations, which a computed-torque law feeds forward, are not the "
             "derivatives of the rates");
  }
  b.atLeast("min_normal_force", f.min_normal_force, 0.0, "a tip in contact pulls on the ground");
  if (f.min_normal_force > 0) {
    b.atMost("max_friction_ratio", f.max_friction_ratio, friction,
             "a tip force leaves the friction cone of the robot's mu: the tip slips");
    b.atLeast("min_foot_cop_margin", f.min_foot_cop_margin, -kGroundTolerance,
              "foot B's centre of pressure leaves the foot: the foot rolls");
  }
  b.atLeast("min_swing_clearance", f.min_swing_clearance, -kGroundTolerance,
            "the swing tip passes below the ground");
  b.atMost("max_joint_rate_use", f.max_joint_rate_use, 1 + kLimitTolerance,
           "a joint turns faster than the robot file's velocity_limit (a config bounds the joints "
           "with constraints.joint_velocity_limits; rate_limit bounds the links)");
  b.atMost("max_torque_use", f.max_torque_use, 1 + kLimitTolerance,
           "a joint torque passes the robot file's torque_limit");
  return b.take();
}

std::vector<std::string> unjudgedChecks(double rate_hz) {
  if (rate_hz >= kDerivativeCheckRateHz) return {};
  return {"max_rate_mismatch", "max_acceleration_mismatch"};
}

}  // namespace gaitopt::gaits
