#pragma once
/// @file mumps_calls.hpp
/// MUMPS's analysis, factorizations and back-solves inside a solve, counted and timed (issue
/// 16: is the linear solver alone already over a time target?). Ipopt 3.11 times its MUMPS
/// calls only as a whole. An executable linking this file defines MUMPS's C entry point
/// dmumps_c itself; the dynamic linker binds Ipopt's calls to that definition (the executable
/// comes first in the symbol lookup), which times the call by its job and passes it on to
/// libdmumps's own (dlsym RTLD_NEXT). Bench executables only.

namespace gaitopt::bench {

/// One kind of MUMPS call: how many and their wall time [s].
struct MumpsPhase {
  int calls = 0;
  double seconds = 0;
};

/// MUMPS's work since the last reset: analysis (JOB = 1), numerical factorization (JOB = 2)
/// and back-solve (JOB = 3).
struct MumpsCalls {
  MumpsPhase analysis, factorization, solve;
};

MumpsCalls mumpsCalls();
void resetMumpsCalls();

}  // namespace gaitopt::bench
