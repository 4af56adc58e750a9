#pragma once
/// @file row_log.hpp
/// The on-disk record of a resumable run (stability sweeps, gait libraries): a CSV with one row
/// per finished point, appended and flushed as soon as the point is done. A killed run keeps
/// every finished row; a rerun reads them back (a torn last line is ignored, so its point is
/// redone, and the torn bytes are cut from the file). Rows are keyed by their first field, or by
/// their first few (a 2-D stability map keys a point by both coordinates); a later row replaces an
/// earlier one.
#include <map>
#include <mutex>
#include <string>
#include <vector>

#include "io/output/checked_write.hpp"

namespace gaitopt::io {

using Row = std::vector<std::string>;

class RowLog {
 public:
  /// Opens (creating with `header`, or reading the rows of) `path`; rows are keyed by their
  /// first `key_fields` fields (1 <= key_fields <= header size).
  /// @throws config::ConfigError when it has another header (bad input), WriteError
  ///         when it cannot be written.
  RowLog(std::string path, Row header, std::size_t key_fields = 1);

  /// The finished rows so far, by their key (keyOf).
  const std::map<std::string, Row>& rows() const { return rows_; }
  /// Appends a row of header().size() fields with one checked write; thread-safe.
  /// @throws WriteError (a full disk): the row is then not counted as finished.
  void append(const Row& row);
  const std::string& path() const { return path_; }
  /// A row's key: its first key_fields fields joined with commas.
  std::string keyOf(const Row& row) const;

 private:
  std::string path_;
  Row header_;
  std::size_t key_fields_;
  std::map<std::string, Row> rows_;
  AppendFile out_;
  std::mutex mutex_;
};

}  // namespace gaitopt::io
