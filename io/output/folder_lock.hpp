#pragma once
/// @file folder_lock.hpp
/// One writer per output folder: DIR.lock next to the folder, held with flock(2) for the run.
/// The kernel drops the lock when the process dies, so a killed run never blocks the next one.
///
/// The lock file is gaitopt's own: it is created with O_EXCL | O_NOFOLLOW and its first line is
/// kLockTag. A DIR.lock that is a link, not a regular file, or does not start with the tag is a
/// user's file: it is neither written nor removed, and the run is refused (exit 2).
#include <string>

namespace gaitopt::io {

/// The first line of every lock file gaitopt writes (the holder's pid follows on the second).
inline constexpr const char* kLockTag = "gaitopt folder lock";

class FolderLock {
 public:
  /// Locks `dir` (creating DIR.lock). @throws config::ConfigError (exit 2) naming the process
  /// that holds it, or when DIR.lock is not gaitopt's; io::WriteError when it cannot be created.
  explicit FolderLock(const std::string& dir);
  /// Removes DIR.lock and releases it (only in the process that took it, not in forked workers).
  ~FolderLock();
  FolderLock(const FolderLock&) = delete;
  FolderLock& operator=(const FolderLock&) = delete;

 private:
  /// One try: true when the lock is held, false when the file was replaced meanwhile.
  bool tryLock(const std::string& dir);

  std::string path_;
  int fd_ = -1;
  int owner_pid_ = 0;
};

}  // namespace gaitopt::io
