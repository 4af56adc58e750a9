#include "ocp/solve/kkt/pair_order.hpp"

#include <Eigen/OrderingMethods>
#include <Eigen/SparseCore>
#include <algorithm>
#include <stdexcept>

namespace gaitopt::ocp::kkt {

namespace {

/// Rows grouped into nodes: a pair's two rows, or one row alone (second -1).
struct Nodes {
  std::vector<int> of;  // row -> its node
  std::vector<int> first, second;
  int size() const { return static_cast<int>(first.size()); }
};

Nodes groupRows(int n, const std::vector<PivotPair>& pairs) {
  Nodes nodes{std::vector<int>(n, -1), {}, {}};
  for (const PivotPair& p : pairs) {
    if (p.first == p.second || nodes.of[p.first] >= 0 || nodes.of[p.second] >= 0)
      throw std::invalid_argument("pairedMinimumDegreeOrder: pairs must be disjoint pairs of rows");
    nodes.of[p.first] = nodes.of[p.second] = nodes.size();
    nodes.first.push_back(p.first);
    nodes.second.push_back(p.second);
  }
  for (int i = 0; i < n; ++i) {
    if (nodes.of[i] >= 0) continue;
    nodes.of[i] = nodes.size();
    nodes.first.push_back(i);
    nodes.second.push_back(-1);
  }
  return nodes;
}

/// The graph of the nodes as a compressed matrix, which Eigen's AMD asks for (each column's rows
/// sorted and distinct): a counting sort by column, a marker per column, a sort of each column.
Eigen::SparseMatrix<double, Eigen::ColMajor, int> nodeGraph(const SymmetricPattern& pattern,
                                                            const Nodes& nodes) {
  const int nb = nodes.size();
  std::vector<int> start(nb + 1, 0);
  for (int c = 0; c < pattern.n; ++c)
    start[nodes.of[c] + 1] += pattern.outer[c + 1] - pattern.outer[c];
  for (int b = 0; b < nb; ++b) start[b + 1] += start[b];
  std::vector<int> rows(start[nb]), next(start.begin(), start.end() - 1), mark(nb, -1);
  for (int col = 0; col < nb; ++col) {
    for (int c : {nodes.first[col], nodes.second[col]}) {
      if (c < 0) continue;
      for (int k = pattern.outer[c]; k < pattern.outer[c + 1]; ++k) {
        const int row = nodes.of[pattern.inner[k]];
        if (mark[row] == col) continue;  // this node's column has it already
        mark[row] = col;
        rows[next[col]++] = row;
      }
    }
  }
  std::vector<int> outer(nb + 1, 0), inner;
  inner.reserve(rows.size());
  for (int b = 0; b < nb; ++b) {
    std::sort(rows.begin() + start[b], rows.begin() + next[b]);
    inner.insert(inner.end(), rows.begin() + start[b], rows.begin() + next[b]);
    outer[b + 1] = static_cast<int>(inner.size());
  }
  const std::vector<double> ones(inner.size(), 1.0);
  return Eigen::Map<const Eigen::SparseMatrix<double, Eigen::ColMajor, int>>(
      nb, nb, outer[nb], outer.data(), inner.data(), ones.data());
}

}  // namespace

EliminationOrder pairedMinimumDegreeOrder(const SymmetricPattern& pattern,
                                          const std::vector<PivotPair>& pairs) {
  const Nodes nodes = groupRows(pattern.n, pairs);
  Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> perm;
  Eigen::AMDOrdering<int>()(nodeGraph(pattern, nodes), perm);
  EliminationOrder order{{}, {0}};
  order.rows.reserve(pattern.n);
  for (int k = 0; k < nodes.size(); ++k) {
    const int b = perm.indices()[k];
    order.rows.push_back(nodes.first[b]);
    if (nodes.second[b] >= 0) order.rows.push_back(nodes.second[b]);
    order.nodeStart.push_back(static_cast<int>(order.rows.size()));
  }
  return order;
}

}  // namespace gaitopt::ocp::kkt
