#include "ocp/solve/kkt/kkt_statistics.hpp"

namespace gaitopt::ocp::kkt {

KktStatistics& threadKktStatistics() {
  thread_local KktStatistics statistics;
  return statistics;
}

}  // namespace gaitopt::ocp::kkt
