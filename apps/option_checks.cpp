#include "apps/option_checks.hpp"

#include <cmath>
#include <cstdlib>
#include <optional>

#include <fmt/format.h>

#include "config/config_error.hpp"

namespace gaitopt::apps {
namespace {

/// The number `text` holds; nullopt for text that is not a number, which CLI11's own conversion
/// reports.
std::optional<double> numberIn(const std::string& text) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (end == text.c_str() || *end != '\0') return std::nullopt;
  return v;
}

/// "" for a finite number.
std::string finiteOrWhy(const std::string& text) {
  const std::optional<double> v = numberIn(text);
  if (!v || std::isfinite(*v)) return "";
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

CLI::Validator quantityRange(const config::Quantity& quantity) {
  return CLI::Validator(
      [quantity](const std::string& text) {
        // NaN and Inf in the words of every other number option.
        if (std::string why = finiteOrWhy(text); !why.empty()) return why;
        const std::optional<double> v = numberIn(text);
        return v ? config::rangeError(quantity, *v) : std::string();
      },
      config::expectation(quantity), std::string(quantity.name));
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
