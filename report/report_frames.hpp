#pragma once
/// @file report_frames.hpp
/// The frames of the report page's animated stick figure: every link's segment at a sequence of
/// times, with the step and the phase, from a gait (one step in the frame of its stance tip B)
/// or from a closed-loop walk's stick.csv (every step in the world frame).
#include <array>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "dynamics/model.hpp"
#include "gaits/trajectory/trajectory.hpp"

namespace gaitopt::report {

struct StickFrame {
  double t = 0;  ///< [s]
  int step = 1;  ///< 1-based
  gaits::Phase phase = gaits::Phase::kSsp;
  std::vector<std::array<double, 4>> links;  ///< x0, y0, x1, y1 of each link [m]
};

/// The gait sampled at `rate_hz` (both knots of a phase switch kept), B at the origin.
std::vector<StickFrame> gaitFrames(const dynamics::Model& model, const gaits::Trajectory& step,
                                   double rate_hz);

/// The frames of a walk's stick.csv (sim/walk/walk_record.hpp). @throws config::ConfigError naming
/// the file and line for a missing column, a bad number or phase, or a frame with missing links.
std::vector<StickFrame> readStickCsv(const std::string& path);

/// Column-wise JSON for the page: {t: [...], step: [...], phase: [...], links: [[[x0,y0,x1,y1],
/// ...], ...]}.
nlohmann::json framesJson(const std::vector<StickFrame>& frames);

}  // namespace gaitopt::report
