#pragma once
/// @file library_folder.hpp
/// A gait library's folder on disk: library.json (what it is a library of: name, base OCP file
/// relative to the folder, grid axes), points/<point>/ (library_point.hpp), index.csv
/// (library_index.hpp) and index.json (the rows in grid order with the counts and the figures of
/// the last run that solved something).
#include <map>
#include <memory>
#include <string>

#include <nlohmann/json.hpp>

#include "library/grid.hpp"
#include "library/interpolation.hpp"
#include "library/library_index.hpp"
#include "library/library_point.hpp"
#include "library/library_run.hpp"
#include "library/schedule.hpp"
#include "ocp/problem/ocp_config.hpp"

namespace gaitopt::library {

/// The file of a library folder that records what it is a library of.
inline constexpr const char* kLibraryFile = "library.json";

/// The grid and base problem a library folder was built from.
struct LibraryFolder {
  Grid grid;
  ocp::OcpConfig base;
};

/// The solved gaits of a library folder's points, each read from its trajectory.csv when first
/// asked for and kept.
class FolderGaits {
 public:
  FolderGaits(std::string dir, const Grid& grid, const dynamics::Model& model)
      : dir_(std::move(dir)), grid_(&grid), model_(&model) {}
  /// The gait of a point, null when the point has no trajectory.csv (not solved).
  /// @throws config::ConfigError for a trajectory.csv that does not fit the model.
  GaitLookup lookup();

 private:
  std::string dir_;
  const Grid* grid_;
  const dynamics::Model* model_;
  std::map<int, std::unique_ptr<gaits::Trajectory>> cache_;
};

/// Reads DIR/library.json and the base OCP file it names (relative to DIR).
/// @throws config::ConfigError when DIR is not a library folder or library.json is malformed.
LibraryFolder readLibraryFolder(const std::string& dir);

/// What library.json records for `setup`: the grid, the base problem's path from the folder, the
/// contents of the library, OCP, robot and guess gait files, the rate and any --set values.
nlohmann::ordered_json libraryClaim(const LibrarySetup& setup);

/// Writes libraryClaim(setup) as library.json, or checks that the one there says the same: the
/// grid, the base problem's path and the contents of the library, OCP, robot and guess gait files,
/// and the rate of the points' trajectories.
/// @throws config::ConfigError when the folder holds a library of another grid, base problem,
///         file contents or rate (a rerun would mix gaits of two libraries in one index).
void claimLibraryFolder(const LibrarySetup& setup);

/// Points finished in earlier runs: solved ones whose trajectory.csv is still there, and failed
/// ones unless `retry_failed`.
ScheduleState previousState(const LibrarySetup& setup, const LibraryIndex& index,
                            bool retry_failed);

/// Writes DIR/index.json: index.json(grid) with "last_run", the figures of `stats`, or of the
/// previous index.json when this run solved nothing (a rerun keeps those of the run that built
/// the library).
void writeIndexJson(const LibrarySetup& setup, const LibraryIndex& index, const RunStats& stats);

}  // namespace gaitopt::library
