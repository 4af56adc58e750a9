#pragma once
/// @file export_warnings.hpp
/// The export contract's verdict on a gait just written (summary.json's between_nodes,
/// gaits/export/export_contract.hpp), told on the terminal: the gait is written, but a
/// controller that follows it meets what is told here.
#include <string>

#include <nlohmann/json.hpp>

namespace gaitopt::apps {

/// One warning on stderr per breach of `between_nodes`, then the checks it leaves unjudged at
/// its rate; each line starts with `command`.
void warnOfBreaches(const std::string& command, const nlohmann::ordered_json& between_nodes);

}  // namespace gaitopt::apps
