#include "apps/option_checks.hpp"

#include <cmath>
#include <cstdlib>

#include <fmt/format.h>

#include "config/config_error.hpp"

namespace gaitopt::apps {
namespace {

/// "" for a finite number (or text that is not a number: CLI11's own conversion reports it).
std::string finiteOrWhy(const std::string& text) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (end == text.c_str() || *end != '\0' || std::isfinite(v)) return "";
  return fmt::format("'{}' is not a finite number", text);
}

void addFiniteChecks(CLI::App& app) {
  for (CLI::Option* opt : app.get_options())
    // CLI11 appends the validators' descriptions: "FLOAT:FLOAT in [0 - 10]".
    if (opt->get_type_name().rfind("FLOAT", 0) == 0)
      opt->check(CLI::Validator(finiteOrWhy, "", "finite"));
  for (CLI::App* sub : app.get_subcommands({})) addFiniteChecks(*sub);
}

}  // namespace

void requireFiniteNumbers(CLI::App& app) {
  addFiniteChecks(app);
}

void requireGridFits(double points, double bytes_per_point, const std::string& source) {
  const double bytes = points * bytes_per_point;
  if (bytes <= kGridMemoryBudget) return;
  throw config::ConfigError(
      source, "", 0,
      fmt::format("a grid of {:.4g} points needs about {:.3g} GB of memory ({:g} B per point), "
                  "more than the {:.3g} GB a run may take: use fewer values per axis (at most "
                  "{:.4g} points)",
                  points, bytes / 1e9, bytes_per_point, kGridMemoryBudget / 1e9,
                  std::floor(kGridMemoryBudget / bytes_per_point)));
}

}  // namespace gaitopt::apps
