#include "ocp/solve/kkt/kkt_observer.hpp"

namespace gaitopt::ocp::kkt {

FactorizationObserver& threadFactorizationObserver() {
  thread_local FactorizationObserver observer;
  return observer;
}

}  // namespace gaitopt::ocp::kkt
