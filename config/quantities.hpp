#pragma once
/// @file quantities.hpp
/// The range and unit of the quantities a user sets: a command-line option, a sweep axis, a config
/// key, a Python argument. Every place that takes one checks it here, so `--mass-error 5` and
/// `--sweep mass_error=5`, or `--rate 1e20` and `write_trajectory(..., rate_hz=1e20)`, are refused
/// alike, in the same words.
#include <array>
#include <numbers>
#include <string>
#include <string_view>

namespace gaitopt::config {

/// A quantity and the values it may take, ends included.
struct Quantity {
  std::string_view name;  ///< its sweep parameter, config key or Python argument name
  double lo, hi;
  std::string_view unit;  ///< SI unit, "" for a pure number
};

// Closed-loop scenarios (gaitopt simulate, stability; Python simulate).
inline constexpr Quantity kPush{"push", -1000, 1000, "N s"};
// Relative errors: -1 would be a massless or zero-length link.
inline constexpr Quantity kMassError{"mass_error", -0.5, 2, ""};
inline constexpr Quantity kLengthError{"length_error", -0.5, 0.5, ""};
inline constexpr Quantity kFriction{"friction", 0, 10, ""};
/// Impedance ground stiffness k of F = k d^n: from a mattress to steel on steel.
inline constexpr Quantity kStiffness{"stiffness", 1e2, 1e12, "N/m^n"};
inline constexpr Quantity kGainScale{"gain_scale", 1e-3, 1e3, ""};
inline constexpr Quantity kSteps{"steps", 1, 100000, ""};
/// Sample rate of a trajectory: at 1 MHz a step's grid already holds 10^6 samples a second.
inline constexpr Quantity kSampleRate{"rate_hz", 1, 1e6, "Hz"};
// A chain state (inspect --state): absolute link angles up to two turns either way, whatever
// range a file wraps them to; rates and accelerations far beyond a walk's.
inline constexpr Quantity kLinkAngle{"theta", -4 * std::numbers::pi, 4 * std::numbers::pi, "rad"};
inline constexpr Quantity kLinkRate{"dtheta", -1e3, 1e3, "rad/s"};
inline constexpr Quantity kLinkAcceleration{"ddtheta", -1e6, 1e6, "rad/s^2"};

inline constexpr std::array kQuantities{kPush,      kMassError, kLengthError,     kFriction,
                                        kStiffness, kGainScale, kSteps,           kSampleRate,
                                        kLinkAngle, kLinkRate,  kLinkAcceleration};

/// What the quantity accepts: "a number in [lo, hi] [unit]".
std::string expectation(const Quantity& q);

/// "" when `value` is in range, else "expected <expectation>, got <value>" (NaN is never in range).
std::string rangeError(const Quantity& q, double value);

/// @throws ConfigError naming `source` and `key` (when not "") for a value out of range.
double requireInRange(const Quantity& q, double value, const std::string& source,
                      const std::string& key = "");

}  // namespace gaitopt::config
