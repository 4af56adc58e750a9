#include "study/study_settings.hpp"

#include <nlohmann/json.hpp>

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

void claimStudyFolder(const StudyConfig& c, const std::vector<std::string>& sets,
                      const std::string& dir) {
  // Files by content, in the order the study reads them (not by path: paths differ between
  // machines and checkouts).
  nlohmann::ordered_json files = nlohmann::ordered_json::array();
  for (const std::string& input : studyInputs(c)) files.push_back(io::fileFingerprint(input));
  nlohmann::ordered_json claim = {{"name", c.name}, {"inputs_fnv1a", files}};
  if (!sets.empty()) claim["set"] = sets;  // keyed only when given: a plain rerun resumes
  io::claimSettings(dir + "/" + kStudyFile, claim);
}

}  // namespace gaitopt::study
