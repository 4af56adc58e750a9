#include "io/folder_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <filesystem>
#include <string>

#include <fmt/format.h>

#include "config/config_error.hpp"
#include "io/checked_write.hpp"

namespace gaitopt::io {
namespace {

/// The pid a holder wrote into the lock file ("?" when unreadable).
std::string holderPid(int fd) {
  char buf[32] = {};
  const ssize_t n = ::pread(fd, buf, sizeof buf - 1, 0);
  return n > 0 ? std::string(buf, static_cast<std::size_t>(n)) : "?";
}

/// Whether `fd` is still the file at `path`: a holder that finished unlinks it, and a lock on
/// the unlinked file would exclude nobody.
bool stillLinked(int fd, const std::string& path) {
  struct stat a {
  }, b{};
  return ::fstat(fd, &a) == 0 && ::stat(path.c_str(), &b) == 0 && a.st_ino == b.st_ino &&
         a.st_dev == b.st_dev;
}

}  // namespace

FolderLock::FolderLock(const std::string& dir) : path_(dir + ".lock"), owner_pid_(::getpid()) {
  const std::filesystem::path parent = std::filesystem::path(path_).parent_path();
  if (!parent.empty()) std::filesystem::create_directories(parent);
  for (int attempt = 0; attempt < 100; ++attempt) {
    fd_ = ::open(path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (fd_ < 0) throw WriteError(fmt::format("{}: cannot create: {}", path_, errnoText(errno)));
    if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
      const std::string pid = holderPid(fd_);
      ::close(fd_);
      fd_ = -1;
      throw config::ConfigError(dir, "", 0,
                                fmt::format("another gaitopt run (pid {}) is writing this folder "
                                            "({} is locked); wait for it or choose another --out",
                                            pid, path_));
    }
    if (stillLinked(fd_, path_)) {
      // The pid only names the holder in the message above: on a full disk it stays unwritten
      // and the run goes on to fail at its first real write, with the reason.
      const std::string pid = std::to_string(owner_pid_);
      static_cast<void>(::ftruncate(fd_, 0) == 0 && ::pwrite(fd_, pid.data(), pid.size(), 0) >= 0);
      return;
    }
    ::close(fd_);  // raced with a holder removing it: take the new file
  }
  throw WriteError(fmt::format("{}: cannot lock: it keeps being replaced", path_));
}

FolderLock::~FolderLock() {
  if (fd_ < 0) return;
  if (::getpid() == owner_pid_) ::unlink(path_.c_str());
  ::close(fd_);
}

}  // namespace gaitopt::io
