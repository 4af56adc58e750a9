#pragma once
/// @file option_checks.hpp
/// Checks every command shares: no NaN or Inf in a number option (CLI11 parses "nan", and a
/// NaN passes every range check), the range of a quantity of config/quantities.hpp, and grids no
/// larger than memory allows.
#include <cstddef>
#include <string>

#include <CLI/CLI.hpp>

#include "config/quantities.hpp"

namespace gaitopt::apps {

/// Adds to every floating-point option of `app` and its subcommands (CLI11 type FLOAT) a check
/// that refuses NaN, Inf and overflowing values (exit 2, option named).
void requireFiniteNumbers(CLI::App& app);

/// The check of an option holding `quantity`: the range a sweep axis or a config key of the same
/// quantity accepts, refused in the same words.
CLI::Validator quantityRange(const config::Quantity& quantity);

/// Memory a command may plan for its grid: beyond it the run would page or die in bad_alloc.
inline constexpr double kGridMemoryBudget = 512.0 * 1024 * 1024;  // [B]

/// @throws config::ConfigError naming `source` when `points` of about `bytes_per_point` each
///         exceed kGridMemoryBudget.
void requireGridFits(double points, double bytes_per_point, const std::string& source);

}  // namespace gaitopt::apps
