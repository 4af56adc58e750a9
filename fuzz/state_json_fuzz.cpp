// Fuzz target: chain-state JSON (configs/states/*.json) through apps::loadState, five links.
#include "apps/state_file.hpp"
#include "fuzz_input.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return gaitopt::fuzz::runLoader(
      data, size, [](const std::string& path) { return gaitopt::apps::loadState(path, 5); });
}
