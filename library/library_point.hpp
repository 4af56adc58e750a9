#pragma once
/// @file library_point.hpp
/// One point of a gait library, solved and written: DIR/points/<point>/ (the same files as
/// `gaitopt optimize`), or DIR/points/<point>.failed/ for a solve that failed.
#include <string>

#include "library/grid.hpp"
#include "library/library_config.hpp"
#include "library/library_index.hpp"
#include "library/schedule.hpp"
#include "ocp/solve/solution_report.hpp"

namespace gaitopt::library {

struct LibrarySetup {
  LibraryConfig config;
  Grid grid;
  std::string out_dir;
  ocp::GaitResultOptions result;  ///< rate and pictures of every point folder
  /// Whether a point that neither its warm start nor its polynomial gait reaches is solved along
  /// the base config's `continuation:` (if it has one) as the last attempt
  bool continuation = true;

  std::string pointDir(int point) const;
};

/// Solves the job's point, from the job's warm start (retimed to the point's phases) or the
/// polynomial gait, from the polynomial gait again when a warm start fails, and last along the
/// base config's continuation (LibrarySetup::continuation). Never throws:
/// a point that cannot even be set up is a row with status "error" and the reason.
IndexRow solveLibraryPoint(const LibrarySetup& setup, const PointJob& job);

/// The row of a point whose worker process died while solving it.
IndexRow crashedPointRow(const LibrarySetup& setup, const PointJob& job, const std::string& why);

}  // namespace gaitopt::library
