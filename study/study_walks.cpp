#include "study/study_walks.hpp"

#include <fmt/format.h>

#include "study/study_solve.hpp"

namespace gaitopt::study {
namespace {

using Json = nlohmann::ordered_json;
using Pointer = nlohmann::json::json_pointer;

/// Steps walked and asked, the largest tracking error and slip, and the failure of the walk in
/// `out`; for a walk that wrote no summary (refused input), its exit status and error.
std::vector<std::string> walkRow(const std::string& out, int status) {
  const auto s = readSummary(out);
  if (!s) return {"", "", "", "", fmt::format("simulate exited {}: {}", status, lastLogLine(out))};
  return {numberText(*s, Pointer("/steps_completed")), numberText(*s, Pointer("/steps_requested")),
          numberText(*s, Pointer("/max_tracking_error")), numberText(*s, Pointer("/max_slip_m")),
          s->value("failure", std::string())};
}

/// value and failure of the sweep's first failing value on one side, or two empty fields.
std::vector<std::string> beyond(const Json& sweep, const char* side) {
  if (!sweep.contains(side)) return {"", ""};
  const Json& f = sweep.at(side);
  return {numberText(f, Pointer("/value")), f.value("failure", std::string())};
}

std::vector<std::vector<std::string>> sweepRows(const std::string& controller,
                                                const std::string& out, int status) {
  const auto s = readSummary(out);
  if (!s || !s->contains("sweeps"))
    return {{controller, "", "", "", "",
             fmt::format("stability exited {}: {}", status, lastLogLine(out)), "", "", "", ""}};
  std::vector<std::vector<std::string>> rows;
  for (const auto& [name, sweep] : s->at("sweeps").items()) {
    std::vector<std::string> row = {controller, name};
    for (const char* key : {"/nominal", "/walks_from", "/walks_to"})
      row.push_back(numberText(sweep, Pointer(key)));
    row.push_back(sweep.value("nominal_failure", std::string()));
    for (const char* side : {"fails_below", "fails_above"})
      for (std::string& field : beyond(sweep, side)) row.push_back(std::move(field));
    rows.push_back(std::move(row));
  }
  return rows;
}

}  // namespace

std::vector<std::string> walkColumns() {
  return {"walk",   "controller",      "plant_option",           "plant",
          "steps",  "steps_requested", "max_tracking_error_rad", "max_slip_m",
          "failure"};
}

std::vector<std::vector<std::string>> walkPoint(const WalkBlock& block, const StudyPoint& point,
                                                const std::string& dir, const StudyTools& t) {
  std::vector<std::vector<std::string>> rows;
  for (const std::string& controller : block.controllers)
    for (const std::string& plant : block.plant_values) {
      const std::string name =
          fmt::format("{}_{}_{}={}", block.name, controller, block.plant_option, plant);
      const std::string out = dir + "/walks/" + point.folder + "/" + name;
      std::vector<std::string> args = {"simulate",
                                       "--reference",
                                       gaitFolder(point, dir),
                                       "--controller",
                                       controller,
                                       "--no-poincare",
                                       "--quiet",
                                       "--" + block.plant_option + "=" + plant};
      for (const std::string& a : optionArgs(block.options)) args.push_back(a);
      const int status = runTool(t, args, out, fmt::format("walk {} {}", point.folder, name));
      std::vector<std::string> row = {block.name, controller, block.plant_option, plant};
      for (std::string& field : walkRow(out, status)) row.push_back(std::move(field));
      rows.push_back(std::move(row));
    }
  return rows;
}

std::vector<std::string> sweepColumns() {
  return {"controller",      "sweep",       "nominal",       "walks_from",  "walks_to",
          "nominal_failure", "fails_below", "failure_below", "fails_above", "failure_above"};
}

std::vector<std::vector<std::string>> sweepPoint(const StabilityBlock& block, std::size_t index,
                                                 const StudyPoint& point, const std::string& dir,
                                                 const StudyTools& t) {
  std::vector<std::vector<std::string>> rows;
  for (const std::string& controller : block.controllers) {
    const std::string out =
        fmt::format("{}/stability/{}/{}_{}", dir, point.folder, index, controller);
    std::vector<std::string> args = {
        "stability", "--reference", gaitFolder(point, dir), "--controller", controller, "--jobs",
        "1",         "--quiet"};
    for (const std::string& a : optionArgs(block.options)) args.push_back(a);
    for (const std::string& s : block.sweeps) args.insert(args.end(), {"--sweep", s});
    const int status = runTool(t, args, out, fmt::format("sweep {} {}", point.folder, controller));
    for (auto& row : sweepRows(controller, out, status)) rows.push_back(std::move(row));
  }
  return rows;
}

}  // namespace gaitopt::study
