#pragma once
/// @file point_problem.hpp
/// The gait problem at one point of a library: the base problem with its step length, slope
/// and speed replaced. A speed v at step length L makes the step last T = L / v; every phase
/// duration (and its bounds) scales by T / T_base, so the SSP/DSP split of the base is kept.
/// The polynomial guess gait keeps its shape: its hip and apex distances scale with L. The base
/// problem's `continuation:` is kept; library_point.cpp runs it only at a point that neither a
/// neighbour's gait nor the polynomial gait reaches without it.
#include <array>

#include "dynamics/model.hpp"
#include "gaits/polynomial/gait_params.hpp"
#include "library/grid.hpp"
#include "ocp/problem/ocp_config.hpp"

namespace gaitopt::library {

struct PointProblem {
  ocp::OcpConfig config;
  gaits::GaitParams guess;  ///< the polynomial gait at this point
  dynamics::Model model;    ///< the robot on this point's slope
};

/// `values`: speed [m/s], step length [m], slope [rad] (library_config.hpp Axis order).
/// @throws config::ConfigError for a bad robot or guess gait file, std::domain_error for a step
///         the legs cannot span.
PointProblem pointProblem(const ocp::OcpConfig& base, const std::array<double, kWalkAxes>& values);

/// The phase durations of `config` (SSP, then DSP if any) [s].
std::vector<double> phaseDurations(const ocp::OcpConfig& config);

}  // namespace gaitopt::library
