#pragma once
/// Forward simulation of the chain for the tests: the integrator itself lives in
/// ocp/transcription/chain_simulation.hpp (shared with bench/ocp_study), re-exported here under
/// gaitopt::test.
#include <vector>

#include "ocp/transcription/chain_simulation.hpp"

namespace gaitopt::test {

using SspObserver = ocp::ChainObserver;
using ocp::simulateChain;
using ocp::simulateSsp;

/// Evenly spaced times from 0 to `duration`, `count` intervals.
inline std::vector<double> evenTimes(double duration, int count) {
  std::vector<double> times;
  for (int k = 0; k <= count; ++k) times.push_back(duration * k / count);
  return times;
}

}  // namespace gaitopt::test
