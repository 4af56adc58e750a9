#pragma once
/// @file pair_order.hpp
/// The elimination order MultifrontalLdl starts from: approximate minimum degree on the graph
/// whose nodes are the pivot pairs of kkt_pairs.hpp (a constraint row with the variable it
/// constrains) and the remaining single rows, the two rows of a pair kept next to each other.
/// Ordering the pairs rather than the rows keeps AMD from placing a constraint row, whose
/// diagonal is zero, where nothing eliminated before it gives it a pivot; the factorization
/// then finds its pivots where the order expects them and delays few.
#include <vector>

#include "ocp/solve/kkt/assembly_tree.hpp"
#include "ocp/solve/kkt/symmetric_pattern.hpp"

namespace gaitopt::ocp::kkt {

/// Two rows meant to be eliminated together as one 2x2 pivot (first < second).
struct PivotPair {
  int first = 0;
  int second = 0;
};

/// The rows in elimination order, each pair a node; the pairs must be disjoint.
/// @throws std::invalid_argument on pairs that share a row or pair a row with itself.
EliminationOrder pairedMinimumDegreeOrder(const SymmetricPattern& pattern,
                                          const std::vector<PivotPair>& pairs);

}  // namespace gaitopt::ocp::kkt
