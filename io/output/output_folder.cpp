#include "io/output/output_folder.hpp"

#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <utility>

#include <fmt/format.h>

#include "config/config_error.hpp"
#include "io/output/checked_write.hpp"

namespace gaitopt::io {
namespace fs = std::filesystem;
namespace {

/// The real path of `p` (its existing part resolved, links included).
fs::path realPath(const std::string& p) {
  std::error_code ec;
  const fs::path r = fs::weakly_canonical(fs::absolute(p), ec);
  return ec ? fs::absolute(p).lexically_normal() : r;
}

/// Whether `outer` is `inner` or one of its ancestors.
bool contains(const fs::path& outer, const fs::path& inner) {
  auto o = outer.begin(), i = inner.begin();
  for (; o != outer.end(); ++o, ++i)
    if (i == inner.end() || *o != *i) return false;
  return true;
}

/// The pid of a leftover NAME.tmp-PID / NAME.old-PID of `base`, or nothing.
std::optional<long> leftoverPid(const std::string& entry, const std::string& base,
                                const char* kind) {
  const std::string prefix = base + kind;
  if (entry.size() <= prefix.size() || entry.compare(0, prefix.size(), prefix) != 0)
    return std::nullopt;
  const std::string digits = entry.substr(prefix.size());
  if (digits.find_first_not_of("0123456789") != std::string::npos || digits.size() > 9)
    return std::nullopt;
  return std::stol(digits);
}

/// A process that has exited but is not yet reaped (a zombie, whose state in /proc/PID/stat is
/// 'Z') still answers kill(pid, 0); it writes nothing more.
bool zombie(long pid) {
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string line;
  if (!std::getline(stat, line)) return false;
  const auto name_end = line.rfind(')');  // the name may hold spaces and parentheses
  return name_end != std::string::npos && name_end + 2 < line.size() && line[name_end + 2] == 'Z';
}

bool alive(long pid) {
  if (pid == ::getpid()) return true;
  return (::kill(static_cast<pid_t>(pid), 0) == 0 || errno == EPERM) && !zombie(pid);
}

/// Whether `dir` is a folder gaitopt may remove: a real folder (no link) that holds the marker,
/// or an empty one.
bool removable(const fs::path& dir) {
  std::error_code ec;
  if (!fs::is_directory(fs::symlink_status(dir, ec))) return false;
  return fs::is_empty(dir, ec) || fs::is_regular_file(fs::symlink_status(dir / kMarker, ec));
}

std::string stagingName(const std::string& out, const char* kind) {
  return out + kind + std::to_string(::getpid());
}

/// @throws config::ConfigError when an existing part of the folders above `out` is a file.
void refuseFileOnPath(const std::string& out, const std::string& option) {
  std::error_code ec;
  for (fs::path a = fs::path(out).parent_path(); !a.empty(); a = a.parent_path()) {
    if (fs::exists(a, ec)) {
      if (fs::is_directory(a, ec)) return;
      throw config::ConfigError(
          option, "", 0,
          fmt::format("'{}' lies below '{}', which is a file, not a folder", out, a.string()));
    }
    if (a == a.parent_path()) return;
  }
}

std::string checkedPath(const std::string& out, const std::vector<std::string>& inputs,
                        const std::string& option) {
  std::string path = normaliseOutPath(out, option);
  refuseFileOnPath(path, option);
  refuseInputs(path, inputs, option);
  refuseInsideResult(path, option);
  return path;
}

/// The lock of `path`. @throws config::ConfigError naming `option` when the folder cannot be made
/// there (a path under /proc, a folder without write permission): a bad --out, not a failure of
/// the run; a full disk stays a WriteError.
FolderLock lockOrRefuse(const std::string& path, const std::string& option) {
  std::error_code ec;
  const bool existed = fs::exists(fs::symlink_status(path, ec));
  const auto refuse = [&](const std::string& reason) {
    if (existed || reason == errnoText(ENOSPC) || reason == errnoText(EDQUOT)) return;
    throw config::ConfigError(
        option, "", 0,
        fmt::format("'{}' cannot be created: {}; choose a folder where you may write", path,
                    reason));
  };
  try {
    return FolderLock(path);
  } catch (const WriteError& e) {
    const std::string what = e.what();  // "PATH: cannot create: REASON"
    const std::size_t at = what.rfind(": ");
    refuse(at == std::string::npos ? what : what.substr(at + 2));
    throw;
  } catch (const fs::filesystem_error& e) {
    refuse(e.code().message());
    throw;
  }
}

/// The marker's second line in a resumable run's folder.
constexpr const char* kResumableLine = "It holds a resumable run's points, written in place.\n";

/// Whether the marker file `marker` says its folder is a resumable run's.
bool markedResumable(const fs::path& marker) {
  std::ifstream in(marker);
  const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  return text.find(kResumableLine) != std::string::npos;
}

/// The marker's lines that start with `key`, the rest of each.
std::vector<std::string> markerLines(const fs::path& marker, const std::string& key) {
  std::ifstream in(marker);
  std::vector<std::string> values;
  for (std::string line; std::getline(in, line);)
    if (line.compare(0, key.size(), key) == 0) values.push_back(line.substr(key.size()));
  return values;
}

/// The marker's lines naming the result's kind and each file it wrote.
constexpr const char* kKindLine = "kind: ";
constexpr const char* kWrittenLine = "written: ";

/// The files under `dir` (relative, generic form), the marker left out.
std::vector<std::string> filesUnder(const fs::path& dir) {
  std::vector<std::string> files;
  for (const auto& entry : fs::recursive_directory_iterator(dir))
    if (!entry.is_directory() && entry.path().filename() != kMarker)
      files.push_back(entry.path().lexically_relative(dir).generic_string());
  return files;
}

/// The files under `dir` that its marker does not list as written by gaitopt (none if the
/// marker lists none: a folder written before markers listed their files).
std::vector<std::string> unlistedFiles(const fs::path& dir) {
  const std::vector<std::string> written = markerLines(dir / kMarker, kWrittenLine);
  std::vector<std::string> unlisted;
  if (written.empty()) return unlisted;
  for (const std::string& f : filesUnder(dir))
    if (std::find(written.begin(), written.end(), f) == written.end()) unlisted.push_back(f);
  return unlisted;
}

/// The first of unlistedFiles ("" if none).
std::string unlistedFile(const fs::path& dir) {
  const std::vector<std::string> unlisted = unlistedFiles(dir);
  return unlisted.empty() ? "" : unlisted.front();
}

/// Adds a "written:" line for each of `files` to the marker.
void appendWritten(const fs::path& marker, const std::vector<std::string>& files) {
  std::ifstream in(marker);
  std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  for (const std::string& f : files) text += kWrittenLine + f + "\n";
  writeFile(marker.string(), text);
}

/// Whether `dir` holds anything besides the marker and `claim`, while `claim` is missing.
bool holdsAnotherResult(const fs::path& dir, const std::string& claim) {
  std::error_code ec;
  if (!fs::is_directory(dir, ec) || fs::exists(dir / claim, ec)) return false;
  for (const auto& entry : fs::directory_iterator(dir, ec))
    if (entry.path().filename() != kMarker) return true;
  return false;
}

/// Creates the staging folder `staging` afresh, marked as gaitopt's.
void makeStaging(const fs::path& staging, const std::string& kind) {
  // A run of an earlier process with our pid (reused) left it: ours only if removable.
  if (fs::exists(fs::symlink_status(staging))) {
    if (!removable(staging))
      throw config::ConfigError(
          staging.string(), "", 0,
          "is in the way of this run's staging folder and was not made by gaitopt: remove it");
    fs::remove_all(staging);
  }
  // create_directory fails on anything that is there, a link included; the marker goes in first
  // so that a run killed while filling it leaves a leftover the next run knows as gaitopt's.
  if (!fs::create_directory(staging))
    throw WriteError(fmt::format("{}: cannot create: it appeared meanwhile", staging.string()));
  try {
    writeMarker(staging.string(), false, kind);
  } catch (const WriteError&) {  // a full disk: nothing may be left behind
    std::error_code ignored;
    fs::remove_all(staging, ignored);
    throw;
  }
}

/// Removes a replaced result. The new one is in place by then, so a result that cannot be
/// removed (files of another user in it) is a warning, not a failure of the run.
void removeOldResult(const fs::path& old) {
  std::error_code ec;
  fs::remove_all(old, ec);
  if (ec)
    fmt::print(stderr,
               "warning: {}: the replaced result could not be removed ({}): remove it "
               "yourself\n",
               old.string(), ec.message());
}

}  // namespace

std::string normaliseOutPath(const std::string& text, const std::string& option) {
  std::string trimmed = text;
  while (trimmed.size() > 1 && trimmed.back() == '/') trimmed.pop_back();
  const fs::path p = fs::path(trimmed).lexically_normal();
  const std::string name = p.filename().string();
  if (trimmed.empty() || name.empty() || name == "." || name == "..")
    throw config::ConfigError(
        option, "", 0,
        fmt::format("'{}' names no folder of its own (not '', '.', '..' or '/'): give a new "
                    "folder such as results/run1",
                    text));
  return p.string();
}

void refuseInputs(const std::string& out, const std::vector<std::string>& inputs,
                  const std::string& option) {
  const fs::path o = realPath(out);
  for (const std::string& input : inputs) {
    if (input.empty()) continue;
    const fs::path i = realPath(input);
    if (contains(o, i) || contains(i, o))
      throw config::ConfigError(option, "", 0,
                                fmt::format("'{}' is, holds or is inside the input '{}' of this "
                                            "command: writing there would destroy it or mix "
                                            "results into it; choose another {}",
                                            out, input, option));
  }
}

void requireOurs(const std::string& dir, const std::string& option) {
  const fs::file_status s = fs::symlink_status(dir);
  if (!fs::exists(s)) return;
  const auto refuse = [&](const std::string& what) {
    throw config::ConfigError(option, "", 0,
                              fmt::format("'{}' {}; gaitopt replaces only folders it wrote "
                                          "(they hold {}): choose another {} or remove it yourself",
                                          dir, what, kMarker, option));
  };
  if (fs::is_symlink(s)) refuse("is a symbolic link");
  if (!fs::is_directory(s)) refuse("is a file, not a folder");
  if (!fs::is_empty(dir) && !fs::exists(fs::path(dir) / kMarker))
    refuse("holds files that gaitopt did not write");
  // A file added to a result since (notes, a robot file kept beside the walk) went with it.
  if (const std::string added = unlistedFile(dir); !added.empty())
    refuse(fmt::format("holds '{}', which gaitopt did not write", added));
}

/// @throws config::ConfigError when `dir` holds a gaitopt result of another kind than `kind`
/// (its marker says which): a walk written over an optimised gait took the gait with it.
void refuseOtherKind(const std::string& dir, const std::string& kind, const std::string& option) {
  const std::vector<std::string> kinds = markerLines(fs::path(dir) / kMarker, kKindLine);
  if (kind.empty() || kinds.empty() || kinds.front() == kind) return;
  throw config::ConfigError(option, "", 0,
                            fmt::format("'{}' holds a gaitopt {} result, which a {} result does "
                                        "not replace: choose another {} or remove it yourself",
                                        dir, kinds.front(), kind, option));
}

void refuseInsideResult(const std::string& out, const std::string& option) {
  const fs::path o = realPath(out);
  for (fs::path a = o.parent_path(); a != a.parent_path(); a = a.parent_path()) {
    std::error_code ec;
    if (!fs::is_regular_file(a / kMarker, ec)) continue;
    if (markedResumable(a / kMarker)) return;
    throw config::ConfigError(
        option, "", 0,
        fmt::format("'{}' lies inside the gaitopt result '{}', which the next run writing there "
                    "replaces whole, this folder with it; choose a folder beside it",
                    out, a.string()));
  }
}

void writeMarker(const std::string& dir, bool resumable, const std::string& kind) {
  std::string text = std::string(
                         "This folder was written by gaitopt; the next gaitopt run writing here "
                         "replaces it.\n") +
                     (resumable ? kResumableLine : "");
  if (!kind.empty()) text += kKindLine + kind + "\n";
  writeFile((fs::path(dir) / kMarker).string(), text);
}

void addWrittenFile(const std::string& dir, const std::string& file) {
  const fs::path marker = fs::path(dir) / kMarker;
  std::error_code ec;
  if (!fs::is_regular_file(marker, ec)) return;
  const std::vector<std::string> written = markerLines(marker, kWrittenLine);
  if (written.empty() || std::find(written.begin(), written.end(), file) != written.end()) return;
  appendWritten(marker, {file});
}

void listAddedFiles(const std::string& dir) {
  const std::vector<std::string> added = unlistedFiles(dir);
  if (!added.empty()) appendWritten(fs::path(dir) / kMarker, added);
}

void listWrittenFiles(const std::string& dir) {
  appendWritten(fs::path(dir) / kMarker, filesUnder(dir));
}

void removeIfOurs(const std::string& dir) {
  if (removable(dir)) fs::remove_all(dir);
}

void cleanLeftovers(const std::string& out) {
  const fs::path target(out);
  const fs::path parent = target.has_parent_path() ? target.parent_path() : fs::path(".");
  const std::string base = target.filename().string();
  std::error_code ec;
  std::optional<fs::path> newest_old;
  std::vector<fs::path> stale;
  for (const auto& entry : fs::directory_iterator(parent, ec)) {
    const std::string name = entry.path().filename().string();
    for (const char* kind : {".tmp-", ".old-"}) {
      const auto pid = leftoverPid(name, base, kind);
      // A leftover is removed or restored only when gaitopt made it (removable): a user's file,
      // link or folder that happens to carry such a name is left alone.
      if (!pid || alive(*pid) || !removable(entry.path())) continue;
      stale.push_back(entry.path());
      if (std::string(kind) == ".old-" && (!newest_old || fs::last_write_time(entry.path(), ec) >
                                                              fs::last_write_time(*newest_old, ec)))
        newest_old = entry.path();
    }
  }
  // A kill between the two renames of write() left the previous result only as OUT.old-PID.
  if (newest_old && !fs::exists(fs::symlink_status(target))) fs::rename(*newest_old, target);
  for (const auto& p : stale)
    if (fs::exists(fs::symlink_status(p))) removeOldResult(p);
}

OutputFolder::OutputFolder(const std::string& out, const std::vector<std::string>& inputs,
                           const std::string& option, std::string kind)
    : path_(checkedPath(out, inputs, option)),
      lock_(lockOrRefuse(path_, option)),
      kind_(std::move(kind)) {
  cleanLeftovers(path_);
  requireOurs(path_, option);
  refuseOtherKind(path_, kind_, option);
  // A library, study or stability folder holds a run's rows and whatever was written into it
  // in place (its marker says so); replaced whole by another command's result, all of it went.
  std::error_code ec;
  if (const fs::path marker = fs::path(path_) / kMarker;
      fs::is_regular_file(marker, ec) && markedResumable(marker))
    throw config::ConfigError(
        option, "", 0,
        fmt::format("'{}' holds a resumable run's results (a library, study or stability "
                    "folder), which this command would replace whole: choose another {} or "
                    "remove it yourself",
                    path_, option));
}

void OutputFolder::write(const std::function<void(const std::string&)>& fill) const {
  const fs::path target(path_);
  const fs::path staging = stagingName(path_, ".tmp-"), old = stagingName(path_, ".old-");
  if (target.has_parent_path()) fs::create_directories(target.parent_path());
  makeStaging(staging, kind_);
  try {
    fill(staging.string());
    listWrittenFiles(staging.string());
  } catch (...) {
    std::error_code ignored;
    fs::remove_all(staging, ignored);
    throw;
  }
  // Two renames: the old result stays whole until the new one is in place.
  if (fs::exists(fs::symlink_status(target))) fs::rename(target, old);
  fs::rename(staging, target);
  removeOldResult(old);
}

ResumableFolder::ResumableFolder(const std::string& dir, const std::vector<std::string>& inputs,
                                 const std::string& claim, const std::string& option)
    : path_(checkedPath(dir, inputs, option)), lock_(lockOrRefuse(path_, option)) {
  requireOurs(path_, option);
  if (holdsAnotherResult(path_, claim))
    throw config::ConfigError(
        option, "", 0,
        fmt::format("'{}' holds another gaitopt result (it has no {}); this command adds rows "
                    "only to a folder of its own kind: choose another {} or remove it",
                    path_, claim, option));
  fs::create_directories(path_);
  writeMarker(path_, true);  // also upgrades the marker of a folder written before it said so
}

}  // namespace gaitopt::io
