#pragma once
/// @file assembly_tree.hpp
/// The symbolic analysis of a multifrontal LDL^T (Duff and Reid 1983; Liu, "The multifrontal
/// method for sparse matrix solution", SIAM Review 34, 1992): for a symmetric pattern and an
/// elimination order, the elimination tree, renumbered in postorder so that the columns of a
/// subtree are consecutive, and its supernodes, each one dense front: the fundamental ones
/// (chains of columns whose factor columns nest), then small ones merged into their parents
/// (relaxed amalgamation as MA57 does it: a child and its parent both with fewer than
/// kAmalgamationColumns columns become one front, at the price of some explicit zeros). A
/// supernode's front holds its own columns and the rows below them in L; its children are the
/// fronts whose contribution blocks it adds up. Delayed pivots (multifrontal_ldl.hpp) enlarge
/// fronts at factorization time; the tree does not change.
#include <vector>

#include "ocp/solve/kkt/symmetric_pattern.hpp"

namespace gaitopt::ocp::kkt {

/// Supernodes with fewer columns than this are merged into a parent that also has fewer.
inline constexpr int kAmalgamationColumns = 16;

/// Rows in elimination order, grouped into nodes that stay together: node k is
/// rows[nodeStart[k] .. nodeStart[k + 1]) (a pivot pair, or one row). The tree is built on the
/// graph of the nodes, so a node never straddles two fronts.
struct EliminationOrder {
  std::vector<int> rows;
  std::vector<int> nodeStart;
  /// Every row a node of its own.
  static EliminationOrder ofRows(std::vector<int> rows);
  /// row -> its node, for a matrix of n rows.
  /// @throws std::invalid_argument if the order does not list every row once in nonempty nodes.
  std::vector<int> nodeOfRows(int n) const;
};

struct AssemblyTree {
  /// order[k]: the row eliminated k-th (the given order's nodes, postordered); position: its
  /// inverse.
  std::vector<int> order, position;
  /// Supernode s owns the positions columns[columnStart[s] .. columnStart[s + 1]) (increasing);
  /// supernodes are numbered children before parents.
  std::vector<int> columnStart, columns;
  /// The rows of L below supernode s, as rows of A (not positions), increasing in position:
  /// rows[rowStart[s] .. rowStart[s + 1]).
  std::vector<int> rowStart, rows;
  std::vector<int> parent;  ///< supernode -> parent supernode, -1 for a root
  /// A's lower-triangle entries by the position-earlier of their row and column: for position
  /// column c, entryStart[c] .. entryStart[c + 1] index `entries` (the stored entry's number).
  std::vector<int> entryStart, entries;

  int supernodes() const { return static_cast<int>(parent.size()); }
};

/// @param order every row once, in nodes.
/// @param mergeBelow supernodes with fewer columns merge into a parent with fewer (1: none do).
/// @throws std::invalid_argument if the order does not list every row once in nonempty nodes.
AssemblyTree analyseAssemblyTree(const SymmetricPattern& pattern, const EliminationOrder& order,
                                 int mergeBelow = kAmalgamationColumns);

}  // namespace gaitopt::ocp::kkt
