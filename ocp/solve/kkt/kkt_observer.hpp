#pragma once
/// @file kkt_observer.hpp
/// A window on every matrix KktSolver factorizes for Ipopt, with the count of negative
/// eigenvalues it reports for it: Ipopt's inertia correction acts on that count, so an audit
/// can hold it against another solver's and against a dense eigendecomposition
/// (bench/inertia_audit.cpp). Per thread, as the statistics (kkt_statistics.hpp): Ipopt calls
/// the solver on the thread that runs the solve. Left empty, nothing is called.
#include <functional>

#include "ocp/solve/kkt/symmetric_pattern.hpp"

namespace gaitopt::ocp::kkt {

/// Called after each factorization with the matrix (`values` in the pattern's entry order) and
/// the negative eigenvalues the factorization counted.
using FactorizationObserver =
    std::function<void(const SymmetricPattern& pattern, const double* values, int negative)>;

/// This thread's observer; assign to it to watch, reset it to stop.
FactorizationObserver& threadFactorizationObserver();

}  // namespace gaitopt::ocp::kkt
