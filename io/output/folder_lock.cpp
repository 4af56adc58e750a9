#include "io/output/folder_lock.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <string>

#include <fmt/format.h>

#include "config/config_error.hpp"
#include "io/output/checked_write.hpp"

namespace gaitopt::io {
namespace {

/// The lock file's text up to 64 bytes ("" when unreadable).
std::string content(int fd) {
  char buf[64] = {};
  const ssize_t n = ::pread(fd, buf, sizeof buf - 1, 0);
  return n > 0 ? std::string(buf, static_cast<std::size_t>(n)) : "";
}

/// The pid a holder wrote on the line after the tag ("?" when it has not written it yet).
std::string holderPid(int fd) {
  const std::string text = content(fd);
  const std::string tag = std::string(kLockTag) + "\n";
  if (text.compare(0, tag.size(), tag) != 0 || text.size() == tag.size()) return "?";
  return text.substr(tag.size(), text.find('\n', tag.size()) - tag.size());
}

/// Whether the file may be taken as gaitopt's: tagged, or empty (a run killed before it wrote
/// the tag; an empty file holds nothing a user could lose).
bool ours(int fd) {
  const std::string text = content(fd);
  return text.empty() || text.rfind(std::string(kLockTag) + "\n", 0) == 0;
}

bool isRegular(int fd) {
  struct stat s {};
  return ::fstat(fd, &s) == 0 && S_ISREG(s.st_mode);
}

/// Whether `fd` is still the file at `path`: a holder that finished unlinks it, and a lock on
/// the unlinked file would exclude nobody.
bool stillLinked(int fd, const std::string& path) {
  struct stat a {
  }, b{};
  return ::fstat(fd, &a) == 0 && ::lstat(path.c_str(), &b) == 0 && a.st_ino == b.st_ino &&
         a.st_dev == b.st_dev;
}

[[noreturn]] void refuseForeign(const std::string& dir, const std::string& lock,
                                const std::string& what) {
  throw config::ConfigError(dir, "", 0,
                            fmt::format("{} {}, so it is not gaitopt's lock file; gaitopt neither "
                                        "writes nor removes it: remove it yourself or choose "
                                        "another --out",
                                        lock, what));
}

}  // namespace

FolderLock::FolderLock(const std::string& dir) : path_(dir + ".lock"), owner_pid_(::getpid()) {
  const std::filesystem::path parent = std::filesystem::path(path_).parent_path();
  if (!parent.empty()) std::filesystem::create_directories(parent);
  for (int attempt = 0; attempt < 100; ++attempt)
    if (tryLock(dir)) return;
  throw WriteError(fmt::format("{}: cannot lock: it keeps being replaced", path_));
}

bool FolderLock::tryLock(const std::string& dir) {
  // O_EXCL and O_NOFOLLOW: a link planted at DIR.lock is never followed, so no file of the
  // user's is written through it. O_NONBLOCK: a FIFO there cannot hang the open.
  bool created = true;
  fd_ = ::open(path_.c_str(), O_RDWR | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
  if (fd_ < 0 && errno == EEXIST) {
    created = false;
    fd_ = ::open(path_.c_str(), O_RDWR | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
    if (fd_ < 0 && errno == ENOENT) return false;  // its holder removed it meanwhile
    if (fd_ < 0 && errno == ELOOP) refuseForeign(dir, path_, "is a symbolic link");
  }
  if (fd_ < 0) throw WriteError(fmt::format("{}: cannot create: {}", path_, errnoText(errno)));
  const auto drop = [this] {
    ::close(fd_);
    fd_ = -1;
  };
  if (!isRegular(fd_)) {
    drop();
    refuseForeign(dir, path_, "is not a regular file");
  }
  if (::flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    const std::string pid = holderPid(fd_);
    drop();
    throw config::ConfigError(dir, "", 0,
                              fmt::format("another gaitopt run (pid {}) is writing this folder "
                                          "({} is locked); wait for it or choose another --out",
                                          pid, path_));
  }
  if (!stillLinked(fd_, path_)) {
    drop();  // raced with a holder removing it: take the new file
    return false;
  }
  if (!created && !ours(fd_)) {
    drop();
    refuseForeign(dir, path_, "does not start with the line '" + std::string(kLockTag) + "'");
  }
  // The pid only names the holder in the message above: on a full disk it stays unwritten and
  // the run goes on to fail at its first real write, with the reason.
  const std::string text = fmt::format("{}\n{}\n", kLockTag, owner_pid_);
  static_cast<void>(::ftruncate(fd_, 0) == 0 && ::pwrite(fd_, text.data(), text.size(), 0) >= 0);
  return true;
}

FolderLock::~FolderLock() {
  if (fd_ < 0) return;
  if (::getpid() == owner_pid_ && stillLinked(fd_, path_)) ::unlink(path_.c_str());
  ::close(fd_);
}

}  // namespace gaitopt::io
