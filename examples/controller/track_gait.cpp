/// @file track_gait.cpp
/// Walks an exported gait (trajectory.csv of `gaitopt poly` or `gaitopt optimize`) for a few
/// steps under computed-torque tracking on the nominal robot, and checks that the walk stays on
/// the reference: every step completed, the angles within 0.01 rad of the reference, and each
/// step advancing the reference's step length (within 1 mm).
/// The file is read with the switch states of the summary.json beside it (the touchdown's pre-
/// and post-impact states and the period's, which its fixed-rate grid does not sample), so give
/// the trajectory.csv inside its gait folder.
/// Usage: track_gait ROBOT.yaml trajectory.csv [STEPS]; exit 0 on the reference, 1 off it,
/// 2 bad input.
#include <cmath>
#include <exception>
#include <iostream>
#include <string>

#include "dynamics/robot_files/robot_config.hpp"
#include "gaits/trajectory/trajectory_csv.hpp"
#include "sim/scenario/scenario.hpp"

namespace {

constexpr double kMaxTrackingError = 0.01;     // [rad]
constexpr double kStepLengthTolerance = 1e-3;  // [m]

bool onReference(const gaitopt::sim::WalkResult& walk, int steps, double step_length) {
  bool ok =
      walk.steps_completed == steps && !walk.fell && walk.max_tracking_error < kMaxTrackingError;
  for (const auto& s : walk.steps) {
    std::cout << "  step: advance " << s.advance << " m, max tracking error "
              << s.max_tracking_error << " rad" << (s.ok ? "" : ", failed: " + s.failure) << '\n';
    ok = ok && std::abs(s.advance - step_length) < kStepLengthTolerance;
  }
  return ok;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3 || argc > 4) {
    std::cerr << "usage: track_gait ROBOT.yaml trajectory.csv [STEPS]\n";
    return 2;
  }
  try {
    const auto robot = gaitopt::dynamics::loadRobot(argv[1]);
    const auto step = gaitopt::gaits::readTrajectoryCsv(argv[2], robot);
    gaitopt::sim::Scenario scenario;  // computed torque, rigid ground, nominal plant
    scenario.steps = argc == 4 ? std::stoi(argv[3]) : 4;
    const auto result = gaitopt::sim::runScenario(robot, gaitopt::sim::Reference(step), scenario);
    std::cout << "track_gait: " << result.walk.steps_completed << " of " << scenario.steps
              << " steps of " << argv[2] << ", max tracking error "
              << result.walk.max_tracking_error << " rad\n";
    const bool ok = onReference(result.walk, scenario.steps, step.stepLength());
    std::cout << (ok ? "track_gait: on the reference\n" : "track_gait: OFF the reference\n");
    return ok ? 0 : 1;
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << '\n';
    return 2;
  }
}
