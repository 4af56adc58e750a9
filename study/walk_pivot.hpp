#pragma once
/// @file walk_pivot.hpp
/// A study's walks as people read them: one row per gait point, walk and controller, one column
/// per plant, each cell the steps walked of those asked and, short of them, where it fell.
#include "study/study_table.hpp"

namespace gaitopt::study {

/// From the table runStudy writes as walks.csv (`point_columns` leading columns name the point).
Table walkPivot(const Table& walks, std::size_t point_columns);

}  // namespace gaitopt::study
