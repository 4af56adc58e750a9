#pragma once
/// @file report_command.hpp
/// `gaitopt report DIR [--robot FILE] [--out FILE] [--no-gif]`: one self-contained HTML page of a
/// result folder (gait, walk, library or stability): the gait as an animated stick figure (play,
/// pause, a time slider, the phases along it), the summary, the folder's tables and its charts
/// inlined. Written to DIR/report.html; a walk also gets walk.gif (plots/walk_gif.py).
#include <string>

#include <CLI/CLI.hpp>

namespace gaitopt::apps {

struct ReportOptions {
  std::string dir;
  std::string robot_path;  ///< for gait folders; configs/robots/<robot>.yaml when empty
  std::string out;         ///< DIR/report.html when empty
  bool gif = true;
};

/// @throws config::ConfigError when DIR is not a result folder, its files are malformed or its
/// gait is of another robot than the one used (report/report_folder.hpp).
void runReport(const ReportOptions& options);
void registerReportCommand(CLI::App& app);

}  // namespace gaitopt::apps
