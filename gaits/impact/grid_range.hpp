#pragma once
/// @file grid_range.hpp
/// Command-line ranges "a:b:n" (n evenly spaced values from a to b) or "a" (one value).
#include <string>

#include "gaits/impact/impact_map.hpp"

namespace gaitopt::gaits {

/// @throws config::ConfigError naming `option` when `text` is not a finite number.
double parseNumber(const std::string& text, const std::string& option);

/// The range, each value multiplied by `scale` (unit conversion).
/// @throws config::ConfigError naming `option` for a malformed range or n outside [1, 1e6].
GridAxis parseRange(const std::string& text, const std::string& option, double scale);

}  // namespace gaitopt::gaits
