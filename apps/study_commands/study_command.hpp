#pragma once
/// @file study_command.hpp
/// `gaitopt study --config FILE --out DIR [--set KEY=VALUE]... [--jobs N] [--quiet]`: a study of
/// configs/studies/*.yaml (study/study_run.hpp): each gait config solved at every combination of
/// the axes' values, each optimum walked and swept in closed loop, the tables written to DIR.
/// Reruns resume in DIR: a run already done is not redone.
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

namespace gaitopt::apps {

struct StudyOptions {
  std::string config_path;
  std::string out_dir;
  std::vector<std::string> sets;
  int jobs = 1;
  bool quiet = false;
};

/// @throws config::ConfigError for a bad study config or output folder.
void runStudyCommand(const StudyOptions& options);
void registerStudyCommand(CLI::App& app);

}  // namespace gaitopt::apps
