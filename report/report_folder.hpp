#pragma once
/// @file report_folder.hpp
/// What the report page of a result folder shows, by the folder's kind: a gait (trajectory.csv:
/// one step animated in the frame of its stance tip), a walk (stick.csv: every step in the world
/// frame), a library (library.json: its first solved point) or a stability sweep (sweeps in
/// summary.json: the reference gait it walked, when still there); the folder's charts and tables.
#include <string>

#include "report/report_page.hpp"

namespace gaitopt::report {

/// The page's content for result folder `dir`; `robot_path` is the robot of a gait ("" =
/// configs/robots/<summary's robot>.yaml).
/// @throws config::ConfigError when `dir` is not a result folder, a file in it is malformed or
/// its gait is not of the robot used (a gait's summary.json, a stability sweep's robot).
ReportContent collectReport(const std::string& dir, const std::string& robot_path);

}  // namespace gaitopt::report
