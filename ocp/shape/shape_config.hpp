#pragma once
/// @file shape_config.hpp
/// The config keys that repeat the gait's phases (docs/design.md#the-problems-shape): `steps`,
/// the steps in one period (periodicity closes after the last), and `variants`, model variants
/// that copy the nominal's phases with their own collocated states, driven by a stated feedback
/// law around the nominal reference (the ensemble of Mordatch, Lowrey and Todorov 2015).
#include <string>
#include <vector>

#include "config/yaml_reader.hpp"

namespace gaitopt::ocp {

/// One model variant: the nominal robot with every link's mass and inertia scaled together (a
/// denser or lighter build of the same shape, as sim/scenario/scenario.cpp's plant mass error),
/// and the model the computed-torque law computes with: the nominal, or the nominal off by Mu's
/// uncertainty case 2 or 3 (sec. 4.3, dynamics/model_variation.hpp muUncertaintyCase), the
/// plant then the variant's own, as `simulate --uncertainty-on controller` walks it.
struct VariantConfig {
  double mass_scale = 1;
  /// Every link's length and CoM offset scaled, as the walks' --length-error: with the
  /// reference's angles the copy's tip lands at step_length times this.
  double length_scale = 1;
  int controller_case = 1;  ///< 1: the controller computes with the nominal model
};

/// The law that drives every variant around the reference, the same gains on every joint.
///  - joint_pd: u = u_ref + kp (q_ref - q) + kd (dq_ref - dq), q = M theta the joint angles
///    (Mu 2.41); kp [N m / rad], kd [N m s / rad].
///  - computed_torque: the closed loop's own law (sim/controllers/tracking_controller.cpp, Mu
///    2.43) on the nominal model: u = the nominal's inverse dynamics at the variant's state for
///    the joint accelerations ddq_ref + kp (q_ref - q) + kd (dq_ref - dq); kp [1/s^2], kd [1/s].
///    In single support only (the double support's computed torque shares the load by the
///    plan's forces); the double support uses joint PD with dsp_kp and dsp_kd.
struct FeedbackGains {
  enum class Law { kJointPd, kComputedTorque };
  Law law = Law::kJointPd;
  double kp = 0;
  double kd = 0;
  double dsp_kp = 0;  ///< computed_torque: the DSP's joint PD [N m / rad]
  double dsp_kd = 0;  ///< [N m s / rad]
};

struct ShapeConfig {
  int steps = 1;                        ///< steps per period
  std::vector<VariantConfig> variants;  ///< besides the nominal (variant 0)
  FeedbackGains feedback;               ///< the law that drives every variant
  /// A variant's state after its last touchdown lies within this Euclidean distance of the
  /// nominal's (angles [rad] and rates [rad/s] alike).
  double end_tolerance = 0;
  /// Weight of the variants' spread about the reference in the cost (variant_sets.hpp, 0: none)
  /// [1 / (rad^2 s)] times the nominal cost's units.
  double spread = 0;
  /// Whether the variants keep the contact conditions (unilateral forces and impulses with their
  /// margins, friction cones, ZMP). Without them a variant is a probe: its departure from the
  /// reference is priced by `spread` instead of constrained (a sensitivity penalty,
  /// docs/optimal_gaits.md#a-third-way-a-sensitivity-penalty).
  bool contact = true;

  int variantCount() const { return 1 + static_cast<int>(variants.size()); }
};

/// The top-level keys ShapeConfig reads, for the root's allowOnly.
const std::vector<std::string>& shapeKeys();

/// Reads the keys of shapeKeys() from the config's root; absent keys leave one step and no
/// variants. @throws config::ConfigError naming the key.
ShapeConfig readShapeConfig(const config::YamlReader& root);

}  // namespace gaitopt::ocp
