#pragma once
/// @file contact_rules.hpp
/// One failure rule on every ground (docs/design.md#the-verification-ladder): the rigid walk
/// (hybrid_walk.hpp) and the free-base walks (free_base_walk.hpp: impedance and LCP grounds) end a
/// walk for the same reasons, named alike, with the same thresholds:
///   a fall       the hip below min_hip_height times the leg length, or the torso leaning more
///                than max_torso_lean from upright;
///   a slip       a tip on the ground moved along it by more than max_slip from where it was set
///                down, within one step (a smaller slide is measured and the walk goes on);
///   a foot rotation  (cop_limit = kFail) the stance foot's centre of pressure, -tau0 / F_By
///                (ground.hpp, the sign of gaits/export/metrics.cpp's ZMP), left [-heel, toe] in
///                single support; with kSaturate (the default) the plant's ankle torque is clipped
///                so the CoP stays on the foot. In double support the trailing foot always
///                saturates: it rolls onto its toe as it unloads, which is walking, not a failure
///                (at the double support's first steps it can also meet the heel);
///   a pull       a stance tip (or the leading tip in double support) whose normal force would
///                have to pull on the ground: it lifts off.
#include <cmath>
#include <limits>
#include <numbers>

#include <nlohmann/json.hpp>

#include "dynamics/centre_of_pressure.hpp"

namespace gaitopt::sim {

/// What happens when the controller asks the stance ankle for more than the foot can carry.
enum class CopLimit {
  kSaturate,  ///< the ankle torque saturates: the CoP stays on the edge of the foot
  kFail,      ///< the walk fails as a foot rotation
};

struct ContactRules {
  double max_slip = 0.01;                        ///< [m] per step
  CopLimit cop_limit = CopLimit::kSaturate;      ///< see the file comment
  double restitution = 0;                        ///< Newton e_n of rigid impacts (rigid ground)
  double min_hip_height = 0.5;                   ///< fraction of the leg length
  double max_torso_lean = std::numbers::pi / 3;  ///< [rad] from upright
};

/// "saturate" or "fail".
const char* toString(CopLimit limit);

/// The rules as summary.json records them (SI units, the lean in degrees as `max_torso_lean_deg`).
nlohmann::ordered_json contactRulesJson(const ContactRules& rules);

/// The failure names, one per rule.
inline constexpr const char* kFallHip = "fall: hip below its limit";
inline constexpr const char* kFallTorso = "fall: torso beyond its lean limit";
inline constexpr const char* kSlip = "slip: a tip slid further than max_slip within the step";
inline constexpr const char* kFootRotation =
    "foot rotation: the stance foot's centre of pressure left [-heel, toe]";
inline constexpr const char* kStanceLiftoff = "stance tip lifts off the ground";
inline constexpr const char* kLeadingLiftoff = "leading tip lifts off the ground";

/// A foot carrying less than this fraction of the robot's weight has no centre of pressure worth
/// recording (the compliant ground's force ripple and a trailing foot about to lift off).
inline constexpr double kLoadedFoot = 0.1;

/// Margin of the single-support CoP -tau0 / F_y inside [-heel, toe], negative outside [m]; +inf
/// when the foot carries less than kLoadedFoot of `weight` [N]. What summary.json records.
inline double loadedCopMargin(double tau0, double force_y, const dynamics::Foot& foot,
                              double weight) {
  if (force_y < kLoadedFoot * weight) return std::numeric_limits<double>::infinity();
  return dynamics::copMargin(dynamics::stanceCop(tau0, force_y), foot);
}

/// |F_t| / F_n of a tip carrying at least kLoadedFoot of `weight` [N], else 0: the share of
/// Coulomb's cone the gait uses (a tip that only touches says nothing about slipping; on the
/// compliant and LCP grounds it is capped at mu, where the tip slides; DART's contact solver
/// returns per-contact forces outside its own cone at some time steps, more than twice mu at a
/// double support's first step, docs/closed_loop.md). What summary.json records as
/// max_friction_ratio.
inline double loadedFrictionRatio(const Eigen::Vector2d& force, double weight) {
  return force.y() < kLoadedFoot * weight ? 0.0 : std::abs(force.x()) / force.y();
}

}  // namespace gaitopt::sim
