// Fuzz target: polynomial gait YAML (configs/gaits/*.yaml) through gaits::loadGait.
#include "fuzz_input.hpp"
#include "gaits/polynomial/gait_params.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return gaitopt::fuzz::runLoader(
      data, size, [](const std::string& path) { return gaitopt::gaits::loadGait(path); });
}
