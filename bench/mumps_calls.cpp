#include "bench/mumps_calls.hpp"

#include <dlfcn.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>

#include <dmumps_c.h>

namespace gaitopt::bench {
namespace {

MumpsCalls calls;

MumpsPhase* phaseOf(int job) {
  switch (job) {
    case 1:
      return &calls.analysis;
    case 2:
      return &calls.factorization;
    case 3:
      return &calls.solve;
    default:
      return nullptr;  // initialisation and termination
  }
}

}  // namespace

MumpsCalls mumpsCalls() {
  return calls;
}

void resetMumpsCalls() {
  calls = {};
}

}  // namespace gaitopt::bench

extern "C" void dmumps_c(DMUMPS_STRUC_C* id) {
  using Entry = void (*)(DMUMPS_STRUC_C*);
  static const auto mumps = reinterpret_cast<Entry>(dlsym(RTLD_NEXT, "dmumps_c"));
  if (mumps == nullptr) {
    std::fputs("mumps_calls: libdmumps's dmumps_c not found\n", stderr);
    std::abort();
  }
  gaitopt::bench::MumpsPhase* phase = gaitopt::bench::phaseOf(id->job);
  const auto start = std::chrono::steady_clock::now();
  mumps(id);
  if (phase == nullptr) return;
  ++phase->calls;
  phase->seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}
