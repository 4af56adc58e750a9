#pragma once
/// @file output_folder.hpp
/// The folder a command writes (--out), made safe (docs/design.md#output-folders-and-failures):
/// - the path is normalised ("DIR/" is DIR); "", ".", "..", "/" are refused (exit 2);
/// - it must not be, contain or lie inside an input of the same command, whether named on the
///   command line or inside a config (compared as real paths);
/// - it must not lie inside another gaitopt result, which a later run writing there would replace
///   whole, unless that result is a resumable run's folder (ResumableFolder), which holds its
///   points in place;
/// - an existing OUT is replaced only when it is a gaitopt folder (the marker file kMarker) or
///   empty, never a regular file, a link or a folder of someone else's files; the marker lists
///   the files the run wrote, and a folder holding others since (a user's notes) is refused, as
///   is one holding a result of another kind (a walk over an optimised gait);
/// - one writer at a time (FolderLock, OUT.lock); OUT.tmp-PID and OUT.old-PID left by killed
///   runs are removed, and an OUT.old-PID without OUT (a kill between the two renames) is
///   restored first, but only when gaitopt made them: folders (not links) holding the marker,
///   or empty. The staging folder carries the marker from its creation on.
#include <functional>
#include <string>
#include <vector>

#include "io/output/folder_lock.hpp"

namespace gaitopt::io {

/// The file that marks a folder as written by gaitopt (and so replaceable by the next run).
inline constexpr const char* kMarker = ".gaitopt-result";

/// `text` without trailing slashes and lexically normal. @throws config::ConfigError naming
/// `option` when it names no folder of its own ("", ".", "..", "/").
std::string normaliseOutPath(const std::string& text, const std::string& option);

/// @throws config::ConfigError when `out` is one of `inputs`, holds one or lies inside one.
void refuseInputs(const std::string& out, const std::vector<std::string>& inputs,
                  const std::string& option);

/// @throws config::ConfigError unless `dir` is absent, an empty folder or a gaitopt folder
/// holding only the files its marker lists (when it lists them).
void requireOurs(const std::string& dir, const std::string& option);

/// @throws config::ConfigError when `out` lies inside a gaitopt result folder other than a
/// resumable one.
void refuseInsideResult(const std::string& out, const std::string& option);

/// Writes the marker into `dir`; `resumable` marks a folder that others may be written into (a
/// library's points); `kind` names the result ("gait", "walk", ...; "" for none).
/// @throws WriteError.
void writeMarker(const std::string& dir, bool resumable = false, const std::string& kind = "");

/// Adds to `dir`'s marker the list of the files `dir` holds, the ones gaitopt wrote: a folder
/// holding any other is not replaced (requireOurs). @throws WriteError.
void listWrittenFiles(const std::string& dir);

/// Adds `file` (relative to `dir`) to the files `dir`'s marker lists, when it lists them: a
/// command that writes into a result (report's page) keeps it replaceable. @throws WriteError.
void addWrittenFile(const std::string& dir, const std::string& file);

/// Adds to `dir`'s marker, when it lists files, every file `dir` holds that it does not list: a
/// command that draws its pictures into its own result once it is in place (and still locked)
/// keeps it replaceable by its next run. @throws WriteError.
void listAddedFiles(const std::string& dir);

/// Removes `dir` when it is a gaitopt folder or empty (e.g. OUT.failed of an earlier failed
/// solve); anything else, a link included, is left alone.
void removeIfOurs(const std::string& dir);

/// Removes OUT.tmp-PID / OUT.old-PID of dead processes, restoring OUT from the newest
/// OUT.old-PID when OUT is missing. Call with OUT locked.
void cleanLeftovers(const std::string& out);

/// A result folder written whole or not at all: fill(staging) writes OUT.tmp-PID, which then
/// replaces OUT by two renames. Checked and locked from construction to destruction.
class OutputFolder {
 public:
  /// Checks `out` against the rules above and locks it; a result of `kind` ("gait", "walk", ...;
  /// "" for any) replaces only a folder of no other kind. @throws config::ConfigError (exit 2).
  OutputFolder(const std::string& out, const std::vector<std::string>& inputs,
               const std::string& option = "--out", std::string kind = "");

  const std::string& path() const { return path_; }

  /// Calls fill(staging) and puts the staging folder in place of OUT. When fill throws, the
  /// staging folder is removed, OUT is untouched and the exception propagates.
  void write(const std::function<void(const std::string&)>& fill) const;

 private:
  std::string path_;
  FolderLock lock_;
  std::string kind_;
};

}  // namespace gaitopt::io

namespace gaitopt::io {

/// A folder a resumable run (stability sweep, gait library, study) writes in place: the same
/// path, input and ownership rules and the same lock as OutputFolder; created with the marker.
/// `claim` names the file in which the run records its settings (io/settings_record.hpp): a
/// folder holding files but not that one is another command's result, and rows added to it
/// would mix two results, so it is refused.
class ResumableFolder {
 public:
  /// @throws config::ConfigError (exit 2), WriteError.
  ResumableFolder(const std::string& dir, const std::vector<std::string>& inputs,
                  const std::string& claim, const std::string& option = "--out");
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  FolderLock lock_;
};

}  // namespace gaitopt::io
