#pragma once
/// @file study_config.hpp
/// configs/studies/*.yaml: a study solves one or more OCP configs at every combination of some
/// config values (the axes, each value set as `--set KEY=VALUE` would), then walks each optimum
/// in closed loop (walk blocks) and sweeps where it stops walking (a stability block). It is
/// what a user would otherwise script around `gaitopt optimize`, `simulate` and `stability`
/// (docs/design.md#studies).
#include <string>
#include <vector>

#include "config/overrides.hpp"

namespace gaitopt::study {

/// The values an axis steps through, each one or more config values set together (a key and
/// its YAML text); `labels` name them in folders, tables and CSV columns.
struct StudyAxis {
  std::string name;  ///< column name (by default the key's last part without list indices)
  std::vector<std::vector<config::Override>> values;
  std::vector<std::string> labels;
};

/// A `gaitopt simulate` option and its value, without the leading "--".
struct ToolOption {
  std::string name;
  std::string value;
};

/// Each optimum walked under each controller on each plant (one option stepped over values).
struct WalkBlock {
  std::string name;
  std::vector<ToolOption> options;  ///< ground, cop-limit, steps, robot, ...
  std::vector<std::string> controllers;
  std::string plant_option;  ///< the option stepped: mass-error, uncertainty-case, ...
  std::vector<std::string> plant_values;
};

/// Each optimum swept by `gaitopt stability` under each controller.
struct StabilityBlock {
  std::vector<ToolOption> options;
  std::vector<std::string> controllers;
  std::vector<std::string> sweeps;  ///< NAME=FROM:TO:COUNT, as --sweep takes them
};

/// Mu's polynomial gait of a gait config on a robot (`gaitopt poly`).
struct PolynomialGait {
  std::string gait;   ///< configs/gaits/*.yaml
  std::string robot;  ///< configs/robots/*.yaml
};

/// The name a polynomial gait's point is written under: its file's stem.
std::string gaitName(const PolynomialGait& poly);

/// An OCP config of the study, under a name of its own with values of its own set (a variant of
/// a shipped problem without a file of its own: the ensemble with the cost of transport).
struct StudyGait {
  std::string name;  ///< the config's file name without .yaml unless the study names it
  std::string path;
  std::vector<config::Override> sets;  ///< the study's sets, then the gait's own
};

struct StudyConfig {
  std::string name;
  std::string path;  ///< of the YAML file
  /// Designed once each, without the axes and sets (which are OCP config values), then walked
  /// and swept as the optima are.
  std::vector<PolynomialGait> polynomial_gaits;
  std::vector<StudyGait> gaits;
  std::vector<config::Override> sets;  ///< set at every point (the leaves of `set`)
  std::vector<StudyAxis> axes;
  /// How a point with a point before it on the last axis starts: from the guess alone (kNone);
  /// also from that point's optimum, the cheaper optimum kept (kPrevious: a warm start reaches
  /// optima a cold start does not); or from that optimum alone (kPreviousOnly: for problems the
  /// guess does not reach, which would spend minutes failing from it).
  enum class WarmStart { kNone, kPrevious, kPreviousOnly };
  WarmStart warm_start = WarmStart::kNone;
  std::vector<WalkBlock> walks;
  /// The file `walks_from` named, whose `walks` are this study's ("" when the study lists its
  /// own): one battery of walks shared by the studies that compare gaits on it.
  std::string walks_file;
  std::vector<StabilityBlock> stability;
};

/// The study of the file `path`; every gait config is loaded with the sets and each axis value
/// so that a bad value fails here, not hours into the run. @throws config::ConfigError naming
/// file, key and expectation.
StudyConfig loadStudyConfig(const std::string& path,
                            const std::vector<config::Override>& overrides = {});

}  // namespace gaitopt::study
