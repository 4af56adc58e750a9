#pragma once
/// @file result_folder.hpp
/// Result folders appear complete or not at all: the files are written into a staging folder
/// next to the target and renamed over it at the end, so an interrupted run never leaves a
/// half-written result under the final name, and a previous result survives a failed run.
#include <functional>
#include <string>

namespace gaitopt::apps {

/// Calls write(staging_dir), then replaces `dir` by the staging folder. When `write` throws,
/// the staging folder is removed, `dir` is untouched, and the exception propagates.
void writeResultFolder(const std::string& dir,
                       const std::function<void(const std::string&)>& write);

}  // namespace gaitopt::apps
