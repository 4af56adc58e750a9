#include "ocp/solve/continuation_options.hpp"

namespace gaitopt::ocp {
namespace {

using config::YamlReader;

void readMesh(const YamlReader& r, ContinuationOptions& o) {
  r.allowOnly({"segments", "until"});
  for (const double s : r.numbers("segments", config::wholeInRange(1, 1000, "")))
    o.mesh_segments.push_back(static_cast<int>(s));
  o.mesh_until = r.numberOr("until", 0.0, config::inRange(0, 1, "(progress)"));
}

/// `none`, or a list of distinct groups.
std::vector<std::string> readParameters(const YamlReader& r) {
  std::vector<std::string> groups = r.choices("parameters", {"none", "margins", "strike", "cost"});
  for (size_t i = 0; i < groups.size(); ++i) {
    if (groups[i] == "none" && groups.size() > 1)
      r.fail("parameters", "expected `none` alone or a list of margins, strike and cost");
    for (size_t j = 0; j < i; ++j)
      if (groups[j] == groups[i]) r.fail("parameters", "'" + groups[i] + "' is listed twice");
  }
  if (groups.front() == "none") groups.clear();
  return groups;
}

}  // namespace

ContinuationOptions readContinuation(const YamlReader& r) {
  r.allowOnly({"steps", "spacing", "cost_start", "parameters", "sequential", "halvings", "retries",
               "retry_mu_init", "mesh"});
  ContinuationOptions o;
  o.enabled = true;
  o.steps = static_cast<int>(r.numberOr("steps", o.steps, config::wholeInRange(1, 100, "")));
  if (r.has("spacing")) o.geometric = r.choice("spacing", {"linear", "geometric"}) == "geometric";
  o.cost_start =
      r.numberOr("cost_start", o.cost_start, config::inRange(1e-12, 1, "(of the weight)"));
  o.halvings =
      static_cast<int>(r.numberOr("halvings", o.halvings, config::wholeInRange(0, 10, "")));
  o.retries = static_cast<int>(r.numberOr("retries", o.retries, config::wholeInRange(0, 5, "")));
  if (r.has("retry_mu_init"))
    o.retry_mu_init = r.numbers("retry_mu_init", config::inRange(1e-9, 1e3, "(barrier)"));
  if (r.has("parameters")) o.parameters = readParameters(r);
  o.sequential = r.booleanOr("sequential", o.sequential);
  if (r.has("mesh")) readMesh(r.map("mesh"), o);
  return o;
}

}  // namespace gaitopt::ocp
