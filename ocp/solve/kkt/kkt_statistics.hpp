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
  int solves = 0;          ///< right-hand sides Ipopt asked to solve for, each refined here
  /// Factorizations with pivoting (MultifrontalLdl): the matrices the static pivots failed on,
  /// and the ones after them in the same solve.
  int pivoting_factorizations = 0;
  /// Of the factorizations, the ones MUMPS made in place of gaitopt's (a pivot below tiny), plus
  /// the re-factorizations by MUMPS of a solve gaitopt's factors left inexact.
  int mumps_fallbacks = 0;
  /// Why, one count per fallback: a pivot below tiny, a solve that refinement left inexact
  /// under the largest pivot threshold.
  int zero_pivot_fallbacks = 0, inexact_fallbacks = 0;
  /// Solves refinement left inexact, each followed by a factorization with pivoting (after the
  /// static pivots), with a larger pivot threshold, or by MUMPS past the largest.
  int inexact_refactorizations = 0;
  /// Rows eliminated in a later front than the order put them in (MultifrontalLdl), summed over
  /// the factorizations: the work the pivoting added to the order's plan.
  long delayed_pivots = 0;
};

KktStatistics& operator+=(KktStatistics& a, const KktStatistics& b);
/// The counts of what happened between two readings b (before) and a (after).
KktStatistics operator-(KktStatistics a, const KktStatistics& b);

/// This thread's counts since it started; a solve reports the difference.
KktStatistics& threadKktStatistics();

}  // namespace gaitopt::ocp::kkt
