// Fuzz target: robot YAML (configs/robots/*.yaml) through dynamics::loadRobot.
#include "dynamics/robot_files/robot_config.hpp"
#include "fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return gaitopt::fuzz::runLoader(
      data, size, [](const std::string& path) { return gaitopt::dynamics::loadRobot(path); });
}
