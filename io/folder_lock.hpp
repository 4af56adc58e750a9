#pragma once
/// @file folder_lock.hpp
/// One writer per output folder: DIR.lock next to the folder, held with flock(2) for the run.
/// The kernel drops the lock when the process dies, so a killed run never blocks the next one.
#include <string>

namespace gaitopt::io {

class FolderLock {
 public:
  /// Locks `dir` (creating DIR.lock). @throws config::ConfigError (exit 2) naming the process
  /// that holds it, io::WriteError when the lock file cannot be created.
  explicit FolderLock(const std::string& dir);
  /// Removes DIR.lock and releases it (only in the process that took it, not in forked workers).
  ~FolderLock();
  FolderLock(const FolderLock&) = delete;
  FolderLock& operator=(const FolderLock&) = delete;

 private:
  std::string path_;
  int fd_ = -1;
  int owner_pid_ = 0;
};

}  // namespace gaitopt::io
