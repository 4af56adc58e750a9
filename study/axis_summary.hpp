#pragma once
/// @file axis_summary.hpp
/// What a study's solves say per gait and per value of each axis: how many converged, median
/// iterations and solve time, the share of KKT factorizations gaitopt's solver left to MUMPS
/// (summary.json's kkt), and how far apart one gait's converged optima lie, as (max - min) /
/// min of their costs (the figures a solver comparison or a mesh study moves).
#include "study/study_config.hpp"
#include "study/study_table.hpp"

namespace gaitopt::study {

/// One row per gait, then one per axis value, from the table runStudy writes as solves.csv.
Table axisSummary(const StudyConfig& config, const Table& solves);

}  // namespace gaitopt::study
