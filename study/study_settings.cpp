#include "study/study_settings.hpp"

#include <filesystem>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "config/config_error.hpp"
#include "io/strict_json.hpp"

#include "io/settings_record.hpp"
#include "ocp/problem/ocp_config.hpp"

namespace gaitopt::study {

std::vector<std::string> studyInputs(const StudyConfig& c) {
  std::vector<std::string> inputs = {c.path};
  for (const PolynomialGait& poly : c.polynomial_gaits)
    inputs.insert(inputs.end(), {poly.gait, poly.robot});
  for (const StudyGait& gait : c.gaits) {
    inputs.push_back(gait.path);
    for (std::string& input : ocp::ocpInputs(ocp::loadOcpConfig(gait.path, gait.sets)))
      if (!input.empty()) inputs.push_back(std::move(input));
  }
  if (!c.walks_file.empty()) inputs.push_back(c.walks_file);
  for (const WalkBlock& walk : c.walks)
    for (const ToolOption& option : walk.options)
      if (option.name == "robot") inputs.push_back(option.value);
  return inputs;
}

namespace {

/// The first input whose contents differ from the folder's record, by name: claimSettings names
/// only the key, a list of fingerprints. A record of another length is left to it to word.
void refuseChangedInput(const std::string& record, const std::vector<std::string>& inputs,
                        const nlohmann::ordered_json& files) {
  if (!std::filesystem::is_regular_file(record)) return;
  const auto recorded = io::readStrictJson(record);
  if (!recorded.is_object() || !recorded.contains("inputs_fnv1a") ||
      recorded["inputs_fnv1a"].size() != files.size())
    return;
  for (std::size_t i = 0; i < files.size(); ++i)
    if (recorded["inputs_fnv1a"][i] != files[i])
      throw config::ConfigError(
          record, "inputs_fnv1a", 0,
          fmt::format("{} has changed since the folder's rows were made (their inputs are "
                      "recorded by content): restore it, or choose another --out",
                      inputs[i]));
}

}  // namespace

void claimStudyFolder(const StudyConfig& c, const std::vector<std::string>& sets,
                      const std::string& dir) {
  // Files by content, in the order the study reads them (not by path: paths differ between
  // machines and checkouts).
  const std::vector<std::string> inputs = studyInputs(c);
  nlohmann::ordered_json files = nlohmann::ordered_json::array();
  for (const std::string& input : inputs) files.push_back(io::fileFingerprint(input));
  refuseChangedInput(dir + "/" + kStudyFile, inputs, files);
  nlohmann::ordered_json claim = {{"name", c.name}, {"inputs_fnv1a", files}};
  if (!sets.empty()) claim["set"] = sets;  // keyed only when given: a plain rerun resumes
  io::claimSettings(dir + "/" + kStudyFile, claim);
}

}  // namespace gaitopt::study
