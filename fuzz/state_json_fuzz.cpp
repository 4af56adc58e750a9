// Fuzz target: chain-state JSON (configs/states/*.json) through gaits::loadState, five links.
#include "fuzz_input.hpp"
#include "gaits/trajectory/state_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return gaitopt::fuzz::runLoader(
      data, size, [](const std::string& path) { return gaitopt::gaits::loadState(path, 5); });
}
