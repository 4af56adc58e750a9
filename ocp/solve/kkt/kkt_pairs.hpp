#pragma once
/// @file kkt_pairs.hpp
/// Which rows of Ipopt's augmented system pair_order.hpp keeps together, as 2x2 pivots.
/// Ipopt factorizes (IpStdAugSystemSolver.cpp)
///   [ W + Sigma_x + dw I      0         J_c^T   J_d^T ]   rows x
///   [        0          Sigma_s + dw I    0      -I   ]   rows s
///   [       J_c               0         -dc I     0   ]   rows y_c
///   [       J_d              -I           0     -dd I ]   rows y_d
/// so its trailing block (the constraint rows) is diagonal and, unless Ipopt regularises, zero.
/// Every constraint row is paired with a variable row it couples to (a matching in the
/// bipartite graph of J, strongest coupling tried first, augmenting paths by Kuhn's method);
/// variable rows given as `mustPair` (those seen with a zero diagonal, whose 1x1 pivot would be
/// zero once their constraint rows are eliminated) are matched first, and an augmenting path
/// never unmatches a row. One of them the constraints cannot take pairs with the strongest free
/// variable it couples to through W. A zero-diagonal row left without a partner is eliminated
/// alone in the order, and the factorization finds it a pivot (MultifrontalLdl).
#include <vector>

#include "ocp/solve/kkt/pair_order.hpp"
#include "ocp/solve/kkt/symmetric_pattern.hpp"

namespace gaitopt::ocp::kkt {

/// First row of the largest trailing diagonal block: the constraint rows (n if there is none).
int constraintRowsStart(const SymmetricPattern& pattern);

/// Variable rows (before `constraintStart`) whose diagonal value is exactly zero.
std::vector<int> zeroDiagonalVariables(const SymmetricPattern& pattern, const double* values,
                                       int constraintStart);

/// Disjoint pairs coupled in these values: (variable, constraint) rows, and (variable, variable)
/// rows for a zero-diagonal variable the constraints could not take; other rows stay 1x1.
std::vector<PivotPair> kktPivotPairs(const SymmetricPattern& pattern, const double* values,
                                     int constraintStart, const std::vector<int>& mustPair);

}  // namespace gaitopt::ocp::kkt
