#pragma once
/// @file library_index.hpp
/// The index of a gait library: index.csv in the library folder, one row per finished solve of a
/// point, appended as it ends (a io::RowLog, row_log.hpp: a rerun skips what is done), so a point
/// retried (its second chance, --retry-failed, a worker that died) has several rows and its last
/// one is its outcome; index.json, written from it at the end of every run, keeps that one.
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "io/row_log.hpp"
#include "library/grid.hpp"

namespace gaitopt::library {

struct IndexRow {
  std::string point;  ///< the point's folder name under points/
  double speed = 0, step_length = 0, slope = 0;
  std::vector<double> config_values;  ///< one per config axis of the grid (Grid::configAxes)
  std::string status;  ///< Ipopt's status, or "error" when the point could not be set up
  bool converged = false;
  double cost = 0;
  double cost_of_transport = 0;       ///< of the optimal gait (absolute work / (m g d))
  double poly_cost_of_transport = 0;  ///< of the polynomial gait at the same point (NaN: none)
  int iterations = 0;
  double solve_time_s = 0;
  std::string start;    ///< "polynomial", "warm:<point>", or "warm:<point>,polynomial" (retried)
  std::string message;  ///< why it failed
};

class LibraryIndex {
 public:
  /// The index of a library over `grid`: a column per axis. @throws std::runtime_error when
  /// index.csv cannot be read or written.
  LibraryIndex(const std::string& dir, const Grid& grid);

  /// The row of a point finished in this or an earlier run.
  std::optional<IndexRow> row(const std::string& point) const;
  /// Appends and flushes; thread-safe.
  void append(const IndexRow& row);
  /// index.json: the grid, the rows in grid order, and the counts.
  nlohmann::ordered_json json(const Grid& grid) const;

 private:
  std::size_t config_axes_;
  io::RowLog log_;
};

nlohmann::ordered_json toJson(const IndexRow& row);
IndexRow indexRowFromJson(const nlohmann::json& j);

}  // namespace gaitopt::library
