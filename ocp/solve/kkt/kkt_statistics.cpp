#include "ocp/solve/kkt/kkt_statistics.hpp"

namespace gaitopt::ocp::kkt {

KktStatistics& operator+=(KktStatistics& a, const KktStatistics& b) {
  a.analyses += b.analyses;
  a.factorizations += b.factorizations;
  a.solves += b.solves;
  a.pivoting_factorizations += b.pivoting_factorizations;
  a.mumps_fallbacks += b.mumps_fallbacks;
  a.zero_pivot_fallbacks += b.zero_pivot_fallbacks;
  a.delayed_pivots += b.delayed_pivots;
  a.inexact_fallbacks += b.inexact_fallbacks;
  a.inexact_refactorizations += b.inexact_refactorizations;
  return a;
}

KktStatistics operator-(KktStatistics a, const KktStatistics& b) {
  a.analyses -= b.analyses;
  a.factorizations -= b.factorizations;
  a.solves -= b.solves;
  a.pivoting_factorizations -= b.pivoting_factorizations;
  a.mumps_fallbacks -= b.mumps_fallbacks;
  a.zero_pivot_fallbacks -= b.zero_pivot_fallbacks;
  a.delayed_pivots -= b.delayed_pivots;
  a.inexact_fallbacks -= b.inexact_fallbacks;
  a.inexact_refactorizations -= b.inexact_refactorizations;
  return a;
}

KktStatistics& threadKktStatistics() {
  thread_local KktStatistics statistics;
  return statistics;
}

}  // namespace gaitopt::ocp::kkt
