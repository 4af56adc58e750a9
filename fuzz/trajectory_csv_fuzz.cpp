// Fuzz target: trajectory.csv through gaits::readTrajectoryCsv for the five-link robot.
#include "dynamics/robot_files/robot_config.hpp"
#include "fuzz_input.hpp"
#include "gaits/trajectory/trajectory_csv.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static const gaitopt::dynamics::Model model =
      gaitopt::dynamics::loadRobot(GAITOPT_SOURCE_DIR "/configs/robots/mu2004_five_link.yaml");
  return gaitopt::fuzz::runLoader(data, size, [](const std::string& path) {
    return gaitopt::gaits::readTrajectoryCsv(path, model);
  });
}
