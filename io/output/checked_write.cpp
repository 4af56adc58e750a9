#include "io/output/checked_write.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

#include <fmt/format.h>

namespace gaitopt::io {
namespace {

[[noreturn]] void fail(const std::string& path, int error) {
  throw WriteError(fmt::format("{}: cannot write: {}", path, errnoText(error)));
}

/// write(2) until all of `text` is out; returns 0 or the errno of the failure.
int writeAll(int fd, std::string_view text) {
  while (!text.empty()) {
    const ssize_t n = ::write(fd, text.data(), text.size());
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return n < 0 ? errno : ENOSPC;  // a zero-byte write makes no progress
    text.remove_prefix(static_cast<std::size_t>(n));
  }
  return 0;
}

}  // namespace

std::string errnoText(int error) {
  return std::strerror(error);
}

namespace {

/// Writes `content` to the open `fd` of the file `path` and closes it; on failure removes `path`
/// and throws naming `shown` (the user's file, not its temporary).
void writeAndClose(int fd, const std::string& path, std::string_view content,
                   const std::string& shown) {
  int error = writeAll(fd, content);
  // close() reports errors a file system defers (NFS, quotas): checked too.
  if (::close(fd) != 0 && error == 0) error = errno;
  if (error != 0) {
    ::unlink(path.c_str());
    fail(shown, error);
  }
}

/// A new file next to `path`, PATH.tmp-PID-N, created with O_EXCL | O_NOFOLLOW: whatever a user
/// or another process put at such a name is neither written through nor replaced.
int createTemporary(const std::string& path, std::string& tmp) {
  for (int n = 0; n < 100; ++n) {
    tmp = fmt::format("{}.tmp-{}-{}", path, ::getpid(), n);
    const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
    if (fd >= 0) return fd;
    if (errno != EEXIST) fail(path, errno);  // the user's file is what cannot be written
  }
  fail(path, EEXIST);
}

}  // namespace

void writeFile(const std::string& path, std::string_view content) {
  // O_NOFOLLOW: a link at `path` is refused (ELOOP), never written through to its target.
  const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_NOFOLLOW | O_CLOEXEC, 0644);
  if (fd < 0) fail(path, errno);
  writeAndClose(fd, path, content, path);
}

void writeFileAtomically(const std::string& path, std::string_view content) {
  std::string tmp;
  writeAndClose(createTemporary(path, tmp), tmp, content, path);
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    const int error = errno;
    ::unlink(tmp.c_str());
    fail(path, error);
  }
}

AppendFile::AppendFile(std::string path) : path_(std::move(path)) {
  fd_ = ::open(path_.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_NOFOLLOW | O_CLOEXEC, 0644);
  if (fd_ < 0) fail(path_, errno);
}

AppendFile::~AppendFile() {
  if (fd_ >= 0) ::close(fd_);
}

void AppendFile::append(std::string_view text) {
  const off_t before = ::lseek(fd_, 0, SEEK_END);
  if (const int error = writeAll(fd_, text); error != 0) {
    // A write cut short (a full disk) would leave a torn row for readers until a resume cuts
    // it: the file goes back to its whole rows.
    if (before >= 0) {
      [[maybe_unused]] const int cut = ::ftruncate(fd_, before);  // best effort: it failed
    }
    fail(path_, error);
  }
}

void AppendFile::truncate(long size) {
  if (::ftruncate(fd_, size) != 0) fail(path_, errno);
}

}  // namespace gaitopt::io
