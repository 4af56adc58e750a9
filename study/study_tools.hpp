#pragma once
/// @file study_tools.hpp
/// How a study starts its runs: each a `gaitopt` child process writing a folder of its own under
/// the study folder (its output in FOLDER.log), each one's numbers read back from the
/// summary.json it wrote. A run whose summary.json is already there is not redone, so an
/// interrupted study resumes where it stopped.
#include <atomic>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "study/study_config.hpp"

namespace gaitopt::study {

struct StudyTools {
  std::string gaitopt;  ///< the gaitopt executable the runs are started with
  std::function<void(const std::string&)> progress;  ///< one line per run started
  /// Runs that ended without a result and not as bad input (killed, or a full disk): shared by
  /// the copies of these tools, counted by runTool; the next run of the study redoes them.
  std::shared_ptr<std::atomic<int>> unfinished = std::make_shared<std::atomic<int>>(0);
};

/// Runs `gaitopt ARGS... --out OUT --no-plots` (output to OUT.log) unless OUT/summary.json
/// exists or an earlier run was refused (bad input or an unrealisable problem, exits 2 and 3,
/// recorded in OUT.exit: it would be refused again); reports `what` through t.progress first. A run
/// that ends without a result otherwise counts in t.unfinished and is started again by the next run
/// of the study. Returns the child's exit status (0 when skipped after a success).
/// @throws std::system_error when the program cannot be started.
int runTool(const StudyTools& t, std::vector<std::string> args, const std::string& out,
            const std::string& what);

/// The last non-empty line of OUT.log (the error of a refused run).
std::string lastLogLine(const std::string& out);

/// `--NAME VALUE` of each option.
std::vector<std::string> optionArgs(const std::vector<ToolOption>& options);

/// DIR/summary.json, or nothing when the run wrote none.
std::optional<nlohmann::ordered_json> readSummary(const std::string& dir);

/// A number of a summary as the tables print it (up to 10 significant digits), "" when absent.
std::string numberText(const nlohmann::ordered_json& summary,
                       const nlohmann::json::json_pointer& at);

}  // namespace gaitopt::study
