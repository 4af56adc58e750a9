#pragma once
/// @file checked_write.hpp
/// Writes whose every step is checked (open, write, close), so a full disk or a lost mount is an
/// error naming the file and the system's reason ("No space left on device"), never a silent
/// empty file and exit 0.
#include <stdexcept>
#include <string>
#include <string_view>

namespace gaitopt::io {

/// A write that failed: "PATH: cannot write: REASON". The tool exits 1 on it.
class WriteError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The system's text for an errno value ("No space left on device").
std::string errnoText(int error);

/// Creates or truncates `path` and writes `content`; checks every write and the close. A link at
/// `path` is refused, not followed.
/// @throws WriteError; a partly written file is removed.
void writeFile(const std::string& path, std::string_view content);

/// Writes `content` to a new PATH.tmp-PID-N (O_EXCL, links not followed) and renames it over
/// `path`: a reader (or a later run after a failure) sees the old file or the new one, whole.
/// @throws WriteError.
void writeFileAtomically(const std::string& path, std::string_view content);

/// A file that only grows (a resumable run's row log): each append is one checked write(2).
class AppendFile {
 public:
  /// Opens (creating) `path` for appending; a link there is refused. @throws WriteError.
  explicit AppendFile(std::string path);
  ~AppendFile();
  AppendFile(const AppendFile&) = delete;
  AppendFile& operator=(const AppendFile&) = delete;

  /// Appends `text` whole or throws WriteError, cutting the file back to its size before it
  /// (no torn row). One writer at a time: another's rows appended in between would be cut too
  /// (RowLog serialises its appends).
  void append(std::string_view text);
  /// Cuts the file to `size` bytes (drops a torn last line). @throws WriteError.
  void truncate(long size);

 private:
  std::string path_;
  int fd_ = -1;
};

}  // namespace gaitopt::io
