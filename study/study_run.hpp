#pragma once
/// @file study_run.hpp
/// A whole study in its folder DIR: every solve (DIR/runs/), walk (DIR/walks/) and sweep
/// (DIR/stability/) not already done, then the tables, each as CSV and markdown:
///   DIR/solves.{csv,md}     one row per point: gait, the axes' labels, the solve's numbers
///   DIR/by_axis.md          per axis value: how many converged, median iterations and time,
///                           the share of KKT factorizations MUMPS made, the spread of optima
///   DIR/walks.{csv,md}      one row per walk (with walk blocks)
///   DIR/walks_by_plant.md   the walks with a column per plant
///   DIR/stability.{csv,md}  one row per sweep (with stability blocks)
#include <string>

#include "study/study_config.hpp"
#include "study/study_tools.hpp"

namespace gaitopt::study {

struct StudyCounts {
  int points = 0, converged = 0, walks = 0, sweeps = 0;
  int unfinished = 0;  ///< runs that ended without a result, to redo (StudyTools::unfinished)
};

/// Runs the study's lines (the points along its last axis, one after another: a warm start needs
/// the point before) on `jobs` workers at once, each run a child process; the tables come out in
/// the same order whatever `jobs` is. Times measured in a study are its runs' own, so a timing
/// study is run with one job.
StudyCounts runStudy(const StudyConfig& config, const std::string& dir, const StudyTools& tools,
                     int jobs = 1);

}  // namespace gaitopt::study
