#pragma once
/// @file sweep_file.hpp
/// One stability sweep on disk: sweep_<parameter>.csv, an io::RowLog (io/row_log.hpp) of one row
/// per walked value, so a rerun skips the values already walked.
#include <map>
#include <string>

#include "io/row_log.hpp"

namespace gaitopt::sim {

struct SweepRow {
  double value = 0;
  int steps_completed = 0, steps_requested = 0;
  bool fell = false;
  std::string failure;
  double max_tracking_error = 0;
  double max_multiplier = -1;  ///< < 0: not computed
  double mean_advance = 0;     ///< [m]
  double wall_time_s = 0;
};

class SweepFile {
 public:
  /// Opens (creating with a header, or reading the rows of) `path`.
  /// @throws std::runtime_error when it cannot be read or written.
  explicit SweepFile(std::string path);

  /// The finished rows so far, by the value's 10-digit text (the key a rerun matches).
  const std::map<std::string, SweepRow>& rows() const { return rows_; }
  bool has(double value) const { return rows_.count(key(value)) > 0; }
  /// Appends and flushes a row; thread-safe.
  void append(const SweepRow& row);
  static std::string key(double value);

 private:
  io::RowLog log_;
  std::map<std::string, SweepRow> rows_;
  std::mutex mutex_;
};

}  // namespace gaitopt::sim
