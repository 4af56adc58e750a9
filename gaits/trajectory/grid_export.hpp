#pragma once
/// @file grid_export.hpp
/// The controller-ready form of a step (docs/design.md#the-export-contract): samples on one
/// fixed-rate grid t_i = i / rate, i = 0..N, time strictly increasing, each sample in the phase
/// it lies in; the states either side of each phase switch and the state at the end of the step
/// kept beside the grid, so the Trajectory (with its same-time switch pairs) is rebuilt exactly.
///
/// Why: a controller runs on one clock and indexes its reference by i = round(t * rate); the
/// old export repeated the touchdown time (pre- and post-impact rows, Mu 2.23-2.30) and ended at
/// the period, off the grid when phase durations are free. A switch now falls inside one sample
/// interval (t_{i-1}, t_i]: sample i is already the post-switch phase (Trajectory::at is
/// right-continuous), and the jump in rates, accelerations and forces is in the switch states.
#include <cstddef>
#include <string>
#include <vector>

#include "gaits/trajectory/trajectory.hpp"

namespace gaitopt::gaits {

/// The two knots of a phase switch at one time: the last of the phase before (pre-impact) and
/// the first of the phase after (post-impact).
struct PhaseSwitch {
  Knot before;
  Knot after;
};

struct GridExport {
  std::string robot;
  double step_length = 0;     ///< [m]
  double rate_hz = 0;         ///< sample rate of the grid [Hz]
  std::vector<Knot> samples;  ///< t_i = i / rate_hz, i = 0..N with N / rate_hz <= the period
  std::vector<PhaseSwitch> switches;  ///< in time order
  Knot end;                           ///< the state at the end of the step (t = the period)
};

/// N + 1, the number of grid times i / rate_hz in [0, end] (rounding of end * rate corrected).
size_t gridSize(double end, double rate_hz);

/// The fewest samples an export may have: fewer are no trajectory a controller could follow, and
/// the plots, the integrals of the summary and the checks between the solver's points would
/// stand on them alone.
inline constexpr size_t kMinExportSamples = 10;

/// @throws config::ConfigError when `rate_hz` samples a step of `duration` [s] fewer than
/// kMinExportSamples times: exportGrid's check, for a command to make before its solves.
void requireExportRate(double duration, double rate_hz);

/// `traj` sampled at t_i = i / rate_hz (Trajectory::at) from 0 to its end time, with its switch
/// pairs and final knot. @throws std::invalid_argument for a rate that is not > 0 or a
/// trajectory that does not start at t = 0; config::ConfigError for a rate that gives fewer than
/// kMinExportSamples samples.
GridExport exportGrid(const Trajectory& traj, double rate_hz);

/// The Trajectory the grid was taken from: the samples with each switch pair and the end knot
/// put back in time order. A sample within 1e-9 s of a switch or of the end is dropped: the
/// stored knots stand for it (a sample exactly at a switch is the post-switch knot).
/// @throws std::invalid_argument as the Trajectory constructor.
Trajectory joinGrid(const std::string& robot, double step_length, const std::vector<Knot>& samples,
                    const std::vector<PhaseSwitch>& switches, const Knot& end);

}  // namespace gaitopt::gaits
