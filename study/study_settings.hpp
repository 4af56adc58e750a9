#pragma once
/// @file study_settings.hpp
/// What defines a study folder's runs, recorded in DIR/study.json by the first run (the
/// contents of the study config and of every file its runs read, and the values given by
/// `--set`), so a rerun under other settings is refused instead of mixing runs of two studies.
#include <string>
#include <vector>

#include "study/study_config.hpp"

namespace gaitopt::study {

/// The file of a study folder that records its settings.
inline constexpr const char* kStudyFile = "study.json";

/// Every file the study's runs read: the study config, the gait configs and what they name (the
/// robot, the guess gait), the robots its walks name.
std::vector<std::string> studyInputs(const StudyConfig& config);

/// Records the settings in DIR/study.json, or compares them with the recorded ones.
/// @throws config::ConfigError (exit 2) naming what differs; io::WriteError.
void claimStudyFolder(const StudyConfig& config, const std::vector<std::string>& sets,
                      const std::string& dir);

}  // namespace gaitopt::study
