#include "apps/export_warnings.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

namespace gaitopt::apps {

void warnOfBreaches(const std::string& command, const nlohmann::ordered_json& between_nodes) {
  for (const auto& b : between_nodes["breaches"])
    fmt::print(stderr, "{}: warning: on the {:g} Hz export {} ({} {:.3g}, bound {:.3g})\n", command,
               between_nodes["rate_hz"].get<double>(), b["meaning"].get<std::string>(),
               b["check"].get<std::string>(), b["value"].get<double>(), b["bound"].get<double>());
  if (between_nodes.contains("unjudged"))
    fmt::print("{}: not judged on this export: {} ({})\n", command,
               fmt::join(between_nodes["unjudged"]["checks"].get<std::vector<std::string>>(), ", "),
               between_nodes["unjudged"]["why"].get<std::string>());
}

}  // namespace gaitopt::apps
