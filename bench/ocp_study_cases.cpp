/// @file ocp_study_cases.cpp
/// The problems of the collocation study and their meshes.
#include <algorithm>
#include <cmath>
#include <string>

#include "bench/ocp_study.hpp"
#include "dynamics/robot_files/robot_config.hpp"
#include "ocp/guess/initial_guess.hpp"

namespace gaitopt::bench {

namespace {

StudyCase load(const std::string& robot, const std::string& file, std::vector<int> meshes) {
  ocp::OcpConfig config =
      ocp::loadOcpConfig(std::string(GAITOPT_SOURCE_DIR) + "/configs/ocp/" + file);
  dynamics::Model model = dynamics::loadRobot(config.robot_path);
  gaits::Trajectory guess = ocp::polynomialGuess(model, config);
  return {robot, std::move(config), std::move(model), std::move(guess), std::move(meshes)};
}

}  // namespace

std::vector<StudyCase> studyCases() {
  std::vector<StudyCase> cases;
  // RABBIT from 4 segments (Kelly 2017 reports 6) to 96, where the open-loop end error of the
  // trapezoidal scheme has reached its asymptotic order.
  cases.push_back(load("rabbit", "rabbit_kelly2017.yaml", {4, 6, 8, 12, 16, 24, 32, 48, 64, 96}));
  // Five-link: the config's 30 SSP + 6 DSP segments halved to doubled.
  cases.push_back(load("five_link", "mu2004_walk.yaml", {10, 15, 20, 30, 45, 60}));
  return cases;
}

ocp::OcpConfig withMesh(ocp::OcpConfig config, int ssp) {
  auto& phases = config.phases;
  if (phases.size() > 1) {
    const double ratio = static_cast<double>(phases.back().segments) / phases.front().segments;
    phases.back().segments = std::max(1, static_cast<int>(std::lround(ratio * ssp)));
    phases.back().mesh.clear();
  }
  phases.front().segments = ssp;
  phases.front().mesh.clear();
  return config;
}

}  // namespace gaitopt::bench
