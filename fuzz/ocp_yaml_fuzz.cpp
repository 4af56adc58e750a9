// Fuzz target: optimal-gait YAML (configs/ocp/*.yaml) through ocp::loadOcpConfig.
#include "fuzz_input.hpp"
#include "ocp/problem/ocp_config.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  return gaitopt::fuzz::runLoader(
      data, size, [](const std::string& path) { return gaitopt::ocp::loadOcpConfig(path); });
}
