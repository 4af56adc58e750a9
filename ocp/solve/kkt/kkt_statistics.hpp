#pragma once
/// @file kkt_statistics.hpp
/// What gaitopt's KKT solver did during one Ipopt solve, counted by the solver itself: Ipopt
/// reaches it through Pardiso's C interface (pardiso_interface.cpp), which has no room for such
/// counts, so they are kept per thread (Ipopt calls the solver on the thread that runs
/// OptimizeTNLP) and read by ocp/solve/ipopt_adapter.cpp before and after the solve.

namespace gaitopt::ocp::kkt {

struct KktStatistics {
  int analyses = 0;        ///< row pairings and block orders (KktSolver::analyse)
  int factorizations = 0;  ///< numerical factorizations asked for by Ipopt
  /// Of those, the ones MUMPS made in place of the static pivots' (a zero pivot or a wrong
  /// inertia), plus the re-factorizations by MUMPS of a solve the static pivots left inexact.
  int mumps_fallbacks = 0;
  /// Why, one count per fallback: a zero static pivot, an inertia other than a KKT matrix's, a
  /// solve that refinement left inexact.
  int zero_pivot_fallbacks = 0, inertia_fallbacks = 0, inexact_fallbacks = 0;
};

KktStatistics& operator+=(KktStatistics& a, const KktStatistics& b);
/// The counts of what happened between two readings b (before) and a (after).
KktStatistics operator-(KktStatistics a, const KktStatistics& b);

/// This thread's counts since it started; a solve reports the difference.
KktStatistics& threadKktStatistics();

}  // namespace gaitopt::ocp::kkt
