#pragma once
/// @file sweep_file.hpp
/// One stability sweep or 2-D map on disk: sweep_<parameter>.csv or map_<a>_<b>.csv, an
/// io::RowLog (io/row_log.hpp) of one row per walked point, so a rerun skips the points already
/// walked. A sweep's rows start with the column `value`; a map's with one column per parameter.
#include <map>
#include <string>
#include <vector>

#include "io/row_log.hpp"

namespace gaitopt::sim {

struct SweepRow {
  double value = 0;  ///< the swept parameter's value (a map's first parameter)
  int steps_completed = 0, steps_requested = 0;
  bool fell = false;
  std::string failure;
  double max_tracking_error = 0;
  double max_multiplier = -1;  ///< < 0: not computed
  double mean_advance = 0;     ///< [m]
  double wall_time_s = 0;
  double value_b = 0;  ///< a map's second parameter's value (unused in a sweep)
};

class SweepFile {
 public:
  /// Opens (creating with a header, or reading the rows of) `path`; `coordinates` names the
  /// leading columns: {"value"} for a sweep, the two parameters' names for a map.
  /// @throws std::runtime_error when it cannot be read or written.
  explicit SweepFile(std::string path, std::vector<std::string> coordinates = {"value"});

  /// The finished rows so far, by key().
  const std::map<std::string, SweepRow>& rows() const { return rows_; }
  bool has(double value) const { return rows_.count(key(value)) > 0; }
  bool has(double a, double b) const { return rows_.count(key(a, b)) > 0; }
  /// The rows of a sweep over `values`, each at its value as the grid holds it. A row read back
  /// from the file holds its 10 digits; the grid's own doubles make a resumed run's summary the
  /// uninterrupted run's. A row for another value (an edited file) is no point of the grid.
  std::map<std::string, SweepRow> rowsAt(const std::vector<double>& values) const;
  /// The rows of a map over a x b, as rowsAt.
  std::map<std::string, SweepRow> rowsAt(const std::vector<double>& a,
                                         const std::vector<double>& b) const;
  /// Appends and flushes a row; thread-safe.
  void append(const SweepRow& row);
  /// A sweep row's key, the value's 10-digit text (what a rerun matches).
  static std::string key(double value);
  /// A map row's key: both values' keys.
  static std::string key(double a, double b);

 private:
  std::string keyOf(const SweepRow& row) const;
  /// The row at grid point (a, b) (b unused in a sweep), if walked, restamped with the grid's
  /// values into `on_grid`.
  void addAt(double a, double b, std::map<std::string, SweepRow>& on_grid) const;

  bool map_;
  io::RowLog log_;
  std::map<std::string, SweepRow> rows_;
  std::mutex mutex_;
};

}  // namespace gaitopt::sim
