#pragma once
/// @file study_points.hpp
/// The solves of a study: each polynomial gait once, then each OCP config at every combination
/// of the axes' values, the last axis varying fastest, each with the folder name it is written
/// under.
#include <optional>
#include <string>
#include <vector>

#include "study/study_config.hpp"

namespace gaitopt::study {

struct StudyPoint {
  std::string gait;                 ///< the config's file name without .yaml
  std::string config;               ///< the OCP config's path, or the polynomial gait's
  std::string robot;                ///< the polynomial gait's robot; empty for an OCP config
  std::vector<std::string> labels;  ///< one per axis
  std::vector<config::Override> overrides;  ///< the study's sets, then one per axis
  std::string folder;  ///< GAIT, then _NAME=LABEL per axis (as a library names its points)
  /// The point before this one on the last axis (same gait and other values), if any.
  std::optional<std::size_t> previous;
};

std::vector<StudyPoint> studyPoints(const StudyConfig& config);

}  // namespace gaitopt::study
