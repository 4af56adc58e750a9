#pragma once
/// @file walk_record.hpp
/// What `gaitopt simulate` writes about a closed-loop walk: walk.csv (every logged sample,
/// thinned to a rate), steps.csv (one row per step) and stick.csv (link end points in the world
/// frame every frame interval, for the stick diagram).
#include <optional>
#include <string>
#include <vector>

#include "dynamics/model.hpp"
#include "sim/walk/hybrid_walk.hpp"

namespace gaitopt::sim {

/// Collects a walk's samples as its log callback.
class WalkRecorder {
 public:
  /// Keeps a sample when at least 1 / rate_hz has passed since the last kept one, plus the last
  /// sample of every phase (so phase switches and the fall are always in the record).
  WalkRecorder(const dynamics::Model& plant, double rate_hz);

  WalkLog log();
  /// Keeps the last sample seen (the end of the walk, or the fall); call after the walk.
  void finish();
  const std::vector<WalkSample>& samples() const { return samples_; }

  /// walk.csv: t, step, phase, stance tip, angles and reference, torques and reference, ground
  /// forces, hip in the world frame.
  void writeWalkCsv(const std::string& path) const;
  /// stick.csv: t, step, link, x0, y0, x1, y1 [m], phase (SSP/DSP) every `frame_interval` seconds.
  void writeStickCsv(const std::string& path, double frame_interval) const;

 private:
  const dynamics::Model* plant_;
  double period_;
  std::vector<WalkSample> samples_;
  std::optional<WalkSample> pending_;  ///< the latest sample not (yet) kept
};

/// steps.csv: step, ok, impact, ssp_duration, dsp_duration, advance, max_tracking_error, slip,
/// min_cop_margin (inf without an actuated ankle), max_friction_ratio, max_foot_tilt [rad],
/// failure, max_tip_penetration_m (StepResult::max_tip_penetration; empty where the ground models
/// the contact, i.e. every ground but the rigid one).
void writeStepsCsv(const WalkResult& walk, const std::string& path);

}  // namespace gaitopt::sim
