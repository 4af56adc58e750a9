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
/// denser or lighter build of the same shape, as sim/scenario/scenario.cpp's plant mass error).
struct VariantConfig {
  double mass_scale = 1;
};

/// Joint PD around the reference, the same gains on every actuated joint:
/// u = u_ref + kp (q_ref - q) + kd (dq_ref - dq), q = M theta the joint angles (Mu 2.41).
struct FeedbackGains {
  double kp = 0;  ///< [N m / rad]
  double kd = 0;  ///< [N m s / rad]
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

  int variantCount() const { return 1 + static_cast<int>(variants.size()); }
};

/// The top-level keys ShapeConfig reads, for the root's allowOnly.
const std::vector<std::string>& shapeKeys();

/// Reads the keys of shapeKeys() from the config's root; absent keys leave one step and no
/// variants. @throws config::ConfigError naming the key.
ShapeConfig readShapeConfig(const config::YamlReader& root);

}  // namespace gaitopt::ocp
