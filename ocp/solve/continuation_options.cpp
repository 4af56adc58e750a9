#include "ocp/solve/continuation_options.hpp"

#include <cmath>

namespace gaitopt::ocp {
namespace {

using config::YamlReader;

int wholeNumber(const YamlReader& r, const std::string& key, double value) {
  if (value != std::floor(value)) r.fail(key, "expected a whole number");
  return static_cast<int>(value);
}

void readMesh(const YamlReader& r, ContinuationOptions& o) {
  r.allowOnly({"segments", "until"});
  for (const double s : r.numbers("segments", config::inRange(1, 1000, "(whole numbers)")))
    o.mesh_segments.push_back(wholeNumber(r, "segments", s));
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
  o.steps = wholeNumber(r, "steps", r.numberOr("steps", o.steps, config::inRange(1, 100, "")));
  if (r.has("spacing")) o.geometric = r.choice("spacing", {"linear", "geometric"}) == "geometric";
  o.cost_start =
      r.numberOr("cost_start", o.cost_start, config::inRange(1e-12, 1, "(of the weight)"));
  o.halvings =
      wholeNumber(r, "halvings", r.numberOr("halvings", o.halvings, config::inRange(0, 10, "")));
  o.retries =
      wholeNumber(r, "retries", r.numberOr("retries", o.retries, config::inRange(0, 5, "")));
  if (r.has("retry_mu_init"))
    o.retry_mu_init = r.numbers("retry_mu_init", config::inRange(1e-9, 1e3, "(barrier)"));
  if (r.has("parameters")) o.parameters = readParameters(r);
  o.sequential = r.booleanOr("sequential", o.sequential);
  if (r.has("mesh")) readMesh(r.map("mesh"), o);
  return o;
}

}  // namespace gaitopt::ocp
