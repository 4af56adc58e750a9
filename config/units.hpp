#pragma once
/// @file units.hpp
/// The angle unit, in the lowest layer: the config reader recognises an angle written in
/// degrees, and every layer above reads it through dynamics/conventions.hpp, which includes
/// this file with the rest of gaitopt's conventions. pi itself is std::numbers::pi.
#include <numbers>

namespace gaitopt {

/// One degree in radians: the one definition (robot files, impact maps and tests give degrees).
inline constexpr double kDeg = std::numbers::pi / 180;

}  // namespace gaitopt
