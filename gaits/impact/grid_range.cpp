#include "gaits/impact/grid_range.hpp"

#include <cmath>
#include <exception>

#include <fmt/format.h>

#include "config/config_error.hpp"

namespace gaitopt::gaits {

double parseNumber(const std::string& text, const std::string& option) {
  size_t used = 0;
  double value = NAN;
  try {
    value = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size() || !std::isfinite(value))
    throw config::ConfigError(option, "", 0, fmt::format("'{}' is not a finite number", text));
  return value;
}

GridAxis parseRange(const std::string& text, const std::string& option, double scale) {
  const size_t c1 = text.find(':');
  if (c1 == std::string::npos) {
    const double v = parseNumber(text, option) * scale;
    return {v, v, 1};
  }
  const size_t c2 = text.find(':', c1 + 1);
  if (c2 == std::string::npos)
    throw config::ConfigError(option, "", 0, fmt::format("'{}': expected a:b:n or a", text));
  const double n = parseNumber(text.substr(c2 + 1), option);
  if (n != std::floor(n) || n < 1 || n > 1e6)
    throw config::ConfigError(option, "", 0,
                              fmt::format("'{}': n must be an integer from 1 to 1e6", text));
  return {parseNumber(text.substr(0, c1), option) * scale,
          parseNumber(text.substr(c1 + 1, c2 - c1 - 1), option) * scale, static_cast<int>(n)};
}

}  // namespace gaitopt::gaits
