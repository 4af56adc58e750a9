/// @file pardiso_interface.cpp
/// KktSolver behind the C entry points of Pardiso >= 4 (pardisoinit, pardiso), the one door
/// through which Debian's Ipopt 3.11 loads a linear solver at run time: with
/// `linear_solver pardiso` it dlopen()s "libpardiso.so" (PardisoLoader.c). This library is built
/// under that name and linked into gaitopt, so the dlopen finds it already loaded by its soname.
/// Ipopt's side of the protocol (IpPardisoSolverInterface.cpp): MTYPE -2 (real symmetric
/// indefinite), the upper triangle by rows 1-based, phases 11 (symbolic), 22 (numeric),
/// 33 (solve, IPARM(6) = 1: the solution overwrites B), -1 (release); it reads the inertia from
/// IPARM(22) and IPARM(23), perturbed pivots from IPARM(14), refinement steps from IPARM(7), and
/// sets the steps allowed in IPARM(8). Errors: -4 a singular matrix (Ipopt then regularises the
/// constraints), -1 inconsistent input, -2 out of memory, -3 any other failure; Ipopt stops on
/// all but -4.
#include <new>
#include <stdexcept>

#include "ocp/solve/kkt/kkt_solver.hpp"
#include "ocp/solve/kkt/pardiso_interface.hpp"

namespace gaitopt::ocp::kkt {
const char* const kLibraryName = "libpardiso.so";
}

namespace {

using gaitopt::ocp::kkt::KktSolver;
using gaitopt::ocp::kkt::SingularMatrix;
using gaitopt::ocp::kkt::SymmetricPattern;

constexpr int kRealSymmetricIndefinite = -2;

// Pardiso's handle PT is 64 opaque pointers; the first holds the solver.
KktSolver*& solverIn(void** handle) {
  return *reinterpret_cast<KktSolver**>(handle);
}

void runPhase(void** handle, int phase, int n, const double* a, const int* ia, const int* ja,
              int nrhs, int* iparm, double* b) {
  KktSolver*& solver = solverIn(handle);
  switch (phase) {
    case 11:
      delete solver;
      solver = nullptr;
      solver = new KktSolver(SymmetricPattern::fromPardiso(n, ia, ja));
      solver->analyse(a);
      return;
    case 22:
      solver->factorize(a);  // a zero static pivot is MUMPS's to factorize: none perturbed
      iparm[13] = 0;
      iparm[21] = n - solver->negativeEigenvalues();
      iparm[22] = solver->negativeEigenvalues();
      return;
    case 33:
      iparm[6] = 0;
      for (int r = 0; r < nrhs; ++r) iparm[6] += solver->solve(a, b + r * n, iparm[7]);
      return;
    case -1:
      delete solver;
      solver = nullptr;
      return;
    default:
      throw std::invalid_argument("phase");
  }
}

}  // namespace

extern "C" {

/// Its presence tells Ipopt's loader that pardiso() takes DPARM (the >= 4.0 interface).
void pardiso_ipopt_newinterface() {}

void pardisoinit(void* pt, const int* /*mtype*/, const int* /*solver*/, int* iparm,
                 double* /*dparm*/, int* error) {
  static_cast<void**>(pt)[0] = nullptr;
  for (int i = 0; i < 64; ++i) iparm[i] = 0;
  *error = 0;
}

void pardiso(void** pt, const int* /*maxfct*/, const int* /*mnum*/, const int* mtype,
             const int* phase, const int* n, const double* a, const int* ia, const int* ja,
             const int* /*perm*/, const int* nrhs, int* iparm, const int* /*msglvl*/, double* b,
             double* /*x*/, int* error, double* /*dparm*/) {
  *error = 0;
  if (*mtype != kRealSymmetricIndefinite || (*phase != -1 && *phase != 11 && !solverIn(pt))) {
    *error = -1;
    return;
  }
  try {
    runPhase(pt, *phase, *n, a, ia, ja, *nrhs, iparm, b);
  } catch (const SingularMatrix&) {
    *error = -4;
  } catch (const std::bad_alloc&) {
    *error = -2;
  } catch (const std::invalid_argument&) {
    *error = -1;
  } catch (const std::exception&) {
    *error = -3;
  }
}

}  // extern "C"
