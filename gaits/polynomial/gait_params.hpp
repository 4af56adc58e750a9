#pragma once
/// @file gait_params.hpp
/// Parameters of the polynomial gait of Mu (2004) ch. 3, in gaitopt's conventions
/// (configs/gaits/*.yaml). Mu's S_L is 2 * step_length (docs/design.md#conventions).
#include <optional>
#include <string>
#include <vector>

#include "config/overrides.hpp"
#include "gaits/polynomial/leg_ik.hpp"

namespace gaitopt::gaits {

/// What the hip-plan search maximises (hip_plan_search.hpp).
enum class HipObjective {
  kDspZmp,  ///< Mu's DSP stability margin: the DSP ZMP between the tips (sec. 3.2.3)
  kZmp,     ///< the least of that and the SSP ZMP's distance inside the stance foot
};

/// How far from mid-swing the apex may lie, in step lengths: |S_m| <= kApexReach * step_length
/// keeps the swing tip at or above the ground (gait_config.cpp).
inline constexpr double kApexReach = 0.296;

struct GaitParams {
  std::string name;
  double step_length = 0;   ///< tip distance at touchdown [m] (Mu S_L / 2)
  double ssp_duration = 0;  ///< T_S [s]
  double dsp_duration = 0;  ///< T_D [s]
  double apex_x = 0;        ///< S_m: swing-tip x at maximum clearance, from the stance tip [m]
  double apex_height = 0;   ///< H_m: maximum clearance [m]
  double hip_height = 0;    ///< H_h [m]
  double hip_bob = 0;       ///< amplitude of y_h = H_h + bob cos(2 pi t / T) [m] (0: constant)
  double hip_start = 0;     ///< S_S0: hip behind the stance tip at SSP start [m] (3.16)
  std::optional<double> hip_dsp_start;           ///< S_D0 (3.20); empty: optimised
  std::optional<double> hip_velocity_start;      ///< V_h1 (3.18); empty: optimised
  std::optional<double> hip_velocity_touchdown;  ///< V_h2 (3.22); empty: optimised
  HipObjective hip_objective = HipObjective::kDspZmp;
  bool hip_start_free = false;   ///< search S_S0 too, from hip_start
  bool hip_height_free = false;  ///< search H_h too, from hip_height
  double torso_angle = 0;        ///< constant theta of the torso [rad]
  /// Ground inclination gamma [rad], > 0 uphill (dynamics/model.hpp: the gait is designed in the
  /// ground frame; only gravity rotates). `gaitopt poly` applies it with dynamics::withSlope.
  double slope = 0;
  KneeDirection knee = KneeDirection::kForward;

  double duration() const { return ssp_duration + dsp_duration; }
  double speed() const { return step_length / duration(); }
};

/// Loads and validates configs/gaits/*.yaml, with `overrides` (`--set KEY=VALUE`) in place of
/// its values. @throws config::ConfigError.
GaitParams loadGait(const std::string& path, const std::vector<config::Override>& overrides = {});

}  // namespace gaitopt::gaits
