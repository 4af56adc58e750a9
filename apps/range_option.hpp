#pragma once
/// @file range_option.hpp
/// Command-line ranges "a:b:n" (n evenly spaced values from a to b) or "a" (one value).
#include <string>

#include "gaits/impact_map.hpp"

namespace gaitopt::apps {

/// @throws config::ConfigError naming `option` when `text` is not a finite number.
double parseNumber(const std::string& text, const std::string& option);

/// The range, each value multiplied by `scale` (unit conversion).
/// @throws config::ConfigError naming `option` for a malformed range or n outside [1, 1e6].
gaits::GridAxis parseRange(const std::string& text, const std::string& option, double scale);

}  // namespace gaitopt::apps
