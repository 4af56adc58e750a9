#include "study/study_tools.hpp"

#include <filesystem>
#include <fstream>

#include <fmt/format.h>

#include "io/exit_code.hpp"
#include "io/output/checked_write.hpp"
#include "io/spawn.hpp"
#include "io/strict_json.hpp"

namespace gaitopt::study {

namespace {

/// The exit status a run recorded in OUT.exit when it wrote no summary, if it did.
std::optional<int> recordedExit(const std::string& out) {
  std::ifstream file(out + ".exit");
  int status = 0;
  if (file >> status) return status;
  return std::nullopt;
}

}  // namespace

int runTool(const StudyTools& t, std::vector<std::string> args, const std::string& out,
            const std::string& what) {
  if (std::filesystem::exists(out + "/summary.json")) return 0;
  if (const auto status = recordedExit(out)) return *status;
  if (t.progress) t.progress(what);
  std::filesystem::create_directories(std::filesystem::path(out).parent_path());
  args.insert(args.begin(), t.gaitopt);
  args.insert(args.end(), {"--out", out, "--no-plots"});
  const int status = io::runProgramInto(args, out + ".log");
  const bool no_result = status != 0 && !std::filesystem::exists(out + "/summary.json") &&
                         !std::filesystem::exists(out + ".failed/summary.json");
  if (!no_result) return status;
  // A run refused as bad input (exit 2) or as a problem no solve can meet (exit 3, e.g. a step
  // the legs cannot span) is refused again: remembered, so a rerun of the study does not start
  // it (deleting OUT.exit does). One killed or stopped by the machine (a full disk) is not: the
  // rerun redoes it.
  if (status == io::kExitInputError || status == io::kExitInfeasible)
    io::writeFileAtomically(out + ".exit", std::to_string(status));
  else
    ++*t.unfinished;
  return status;
}

std::string lastLogLine(const std::string& out) {
  std::ifstream log(out + ".log");
  std::string line, last;
  while (std::getline(log, line))
    if (!line.empty()) last = line;
  return last;
}

std::vector<std::string> optionArgs(const std::vector<ToolOption>& options) {
  std::vector<std::string> args;
  for (const ToolOption& o : options) args.push_back("--" + o.name + "=" + o.value);
  return args;
}

std::optional<nlohmann::ordered_json> readSummary(const std::string& dir) {
  const std::string path = dir + "/summary.json";
  if (!std::filesystem::exists(path)) return std::nullopt;
  return io::readStrictJson(path);
}

std::string numberText(const nlohmann::ordered_json& summary,
                       const nlohmann::json::json_pointer& at) {
  if (!summary.contains(at) || !summary.at(at).is_number()) return "";
  return fmt::format("{:.10g}", summary.at(at).get<double>());
}

}  // namespace gaitopt::study
