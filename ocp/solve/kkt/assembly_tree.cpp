#include "ocp/solve/kkt/assembly_tree.hpp"

#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <utility>

namespace gaitopt::ocp::kkt {

EliminationOrder EliminationOrder::ofRows(std::vector<int> rows) {
  std::vector<int> start(rows.size() + 1);
  std::iota(start.begin(), start.end(), 0);
  return {std::move(rows), std::move(start)};
}

namespace {

void refuse() {
  throw std::invalid_argument("the elimination order must list every row once, in nonempty nodes");
}

}  // namespace

std::vector<int> EliminationOrder::nodeOfRows(int n) const {
  if (static_cast<int>(rows.size()) != n || nodeStart.empty() || nodeStart.front() != 0 ||
      nodeStart.back() != n)
    refuse();
  std::vector<int> node(n, -1);
  for (size_t k = 0; k + 1 < nodeStart.size(); ++k) {
    if (nodeStart[k + 1] <= nodeStart[k]) refuse();
    for (int q = nodeStart[k]; q < nodeStart[k + 1]; ++q) {
      const int row = rows[q];
      if (row < 0 || row >= n || node[row] >= 0) refuse();
      node[row] = static_cast<int>(k);
    }
  }
  return node;
}

namespace {

/// The graph of the nodes: for each node, the later nodes it couples to (sorted, distinct).
std::vector<std::vector<int>> laterNeighbours(const SymmetricPattern& pattern,
                                              const std::vector<int>& node, int nodes) {
  std::vector<std::vector<int>> later(nodes);
  for (int c = 0; c < pattern.n; ++c)
    for (int k = pattern.outer[c]; k < pattern.outer[c + 1]; ++k) {
      const int a = node[pattern.inner[k]], b = node[c];
      if (a != b) later[std::min(a, b)].push_back(std::max(a, b));
    }
  for (std::vector<int>& l : later) {
    std::sort(l.begin(), l.end());
    l.erase(std::unique(l.begin(), l.end()), l.end());
  }
  return later;
}

/// Elimination tree of the node graph, nodes in their order (Liu's algorithm with path
/// compression; cs_etree of Davis, "Direct Methods for Sparse Linear Systems", 2006, sec. 4.1).
std::vector<int> eliminationTree(const std::vector<std::vector<int>>& later) {
  const int n = static_cast<int>(later.size());
  std::vector<std::vector<int>> earlier(n);  // for node k, the earlier nodes it couples to
  for (int j = 0; j < n; ++j)
    for (int i : later[j]) earlier[i].push_back(j);
  std::vector<int> parent(n, -1), ancestor(n, -1);
  for (int k = 0; k < n; ++k)
    for (int start : earlier[k])
      for (int i = start; i != -1 && i < k;) {
        const int next = ancestor[i];
        ancestor[i] = k;
        if (next == -1) parent[i] = k;
        i = next;
      }
  return parent;
}

/// Nodes in a depth-first postorder of the forest (children in increasing order).
std::vector<int> postorder(const std::vector<int>& parent) {
  const int n = static_cast<int>(parent.size());
  std::vector<int> head(n, -1), next(n, -1), post, stack;
  post.reserve(n);
  for (int j = n - 1; j >= 0; --j) {
    if (parent[j] < 0) continue;
    next[j] = head[parent[j]];
    head[parent[j]] = j;
  }
  for (int root = 0; root < n; ++root) {
    if (parent[root] >= 0) continue;
    stack.push_back(root);
    while (!stack.empty()) {
      const int top = stack.back();
      if (head[top] >= 0) {  // descend to the next unvisited child
        const int child = head[top];
        head[top] = next[child];
        stack.push_back(child);
      } else {
        stack.pop_back();
        post.push_back(top);
      }
    }
  }
  return post;
}

/// The nodes below every node in L (sorted): its own later neighbours merged with its
/// children's structures (Liu 1992, sec. 3).
std::vector<std::vector<int>> nodeStructures(const std::vector<std::vector<int>>& later,
                                             const std::vector<int>& parent) {
  const int n = static_cast<int>(later.size());
  std::vector<std::vector<int>> structure(n), children(n);
  std::vector<int> mark(n, -1);
  for (int j = 0; j < n; ++j)
    if (parent[j] >= 0) children[parent[j]].push_back(j);
  for (int j = 0; j < n; ++j) {
    std::vector<int>& s = structure[j];
    auto add = [&](int i) {
      if (i <= j || mark[i] == j) return;
      mark[i] = j;
      s.push_back(i);
    };
    for (int i : later[j]) add(i);
    for (int c : children[j])
      for (int i : structure[c]) add(i);
    std::sort(s.begin(), s.end());
  }
  return structure;
}

/// Fundamental supernodes as ranges of nodes [first[s], first[s + 1]): node j + 1 continues
/// j's if j is its only child and L's nodes below j are those below j + 1, and j + 1.
std::vector<int> fundamentalSupernodes(const std::vector<int>& parent,
                                       const std::vector<std::vector<int>>& structure) {
  const int n = static_cast<int>(parent.size());
  std::vector<int> children(n, 0), first;
  for (int j = 0; j < n; ++j)
    if (parent[j] >= 0) ++children[parent[j]];
  for (int j = 0; j < n; ++j) {
    const bool continues = j > 0 && parent[j - 1] == j && children[j] == 1 &&
                           structure[j - 1].size() == structure[j].size() + 1;
    if (!continues) first.push_back(j);
  }
  first.push_back(n);
  return first;
}

/// For each fundamental supernode the top of the group it is merged into (itself if none):
/// bottom-up, a supernode joins its parent's group when both groups have fewer than mergeBelow
/// columns (rows of A).
std::vector<int> amalgamate(std::vector<int> size, const std::vector<int>& parent, int mergeBelow) {
  const int nf = static_cast<int>(parent.size());
  std::vector<int> into(nf);
  std::iota(into.begin(), into.end(), 0);
  for (int f = 0; f < nf; ++f) {  // children before parents: f's group is complete
    const int p = parent[f];
    if (p < 0 || size[f] >= mergeBelow || size[p] >= mergeBelow) continue;
    size[p] += size[f];
    into[f] = p;
  }
  for (int f = nf - 1; f >= 0; --f)  // parents before children: point at the group's top
    if (into[f] != f) into[f] = into[into[f]];
  return into;
}

/// A's entries grouped by the earlier position of their two ends: a counting sort.
void bucketEntries(const SymmetricPattern& pattern, AssemblyTree& tree) {
  std::vector<int> key(pattern.nonZeros());
  tree.entryStart.assign(pattern.n + 1, 0);
  for (int c = 0; c < pattern.n; ++c)
    for (int k = pattern.outer[c]; k < pattern.outer[c + 1]; ++k) {
      key[k] = std::min(tree.position[pattern.inner[k]], tree.position[c]);
      ++tree.entryStart[key[k] + 1];
    }
  for (int i = 0; i < pattern.n; ++i) tree.entryStart[i + 1] += tree.entryStart[i];
  std::vector<int> next(tree.entryStart.begin(), tree.entryStart.end() - 1);
  tree.entries.resize(pattern.nonZeros());
  for (int k = 0; k < pattern.nonZeros(); ++k) tree.entries[next[key[k]]++] = k;
}

/// The given order's nodes in the postorder of their tree (the same tree, relabelled).
EliminationOrder postordered(const SymmetricPattern& pattern, const EliminationOrder& order) {
  const int nodes = static_cast<int>(order.nodeStart.size()) - 1;
  EliminationOrder result{{}, {0}};
  for (int k :
       postorder(eliminationTree(laterNeighbours(pattern, order.nodeOfRows(pattern.n), nodes)))) {
    result.rows.insert(result.rows.end(), order.rows.begin() + order.nodeStart[k],
                       order.rows.begin() + order.nodeStart[k + 1]);
    result.nodeStart.push_back(static_cast<int>(result.rows.size()));
  }
  return result;
}

}  // namespace

AssemblyTree analyseAssemblyTree(const SymmetricPattern& pattern, const EliminationOrder& given,
                                 int mergeBelow) {
  const EliminationOrder order = postordered(pattern, given);
  const std::vector<int>& start = order.nodeStart;
  const int nodes = static_cast<int>(start.size()) - 1;
  const std::vector<std::vector<int>> later =
      laterNeighbours(pattern, order.nodeOfRows(pattern.n), nodes);
  const std::vector<int> parent = eliminationTree(later);
  const std::vector<std::vector<int>> structure = nodeStructures(later, parent);
  AssemblyTree tree;
  tree.order = order.rows;
  tree.position.assign(pattern.n, 0);
  for (int k = 0; k < pattern.n; ++k) tree.position[tree.order[k]] = k;
  bucketEntries(pattern, tree);

  const std::vector<int> fundamental = fundamentalSupernodes(parent, structure);
  const int nf = static_cast<int>(fundamental.size()) - 1;
  std::vector<int> fundamentalParent(nf), supernodeOf(nodes), size(nf);
  for (int f = 0; f < nf; ++f) {
    for (int j = fundamental[f]; j < fundamental[f + 1]; ++j) supernodeOf[j] = f;
    size[f] = start[fundamental[f + 1]] - start[fundamental[f]];
  }
  for (int f = 0; f < nf; ++f) {
    const int next = parent[fundamental[f + 1] - 1];
    fundamentalParent[f] = next < 0 ? -1 : supernodeOf[next];
  }
  const std::vector<int> into = amalgamate(size, fundamentalParent, mergeBelow);
  // One supernode per group, numbered by its top (children before parents): its columns, the
  // rows below its top (a merged child's rows below lie in its parent's columns or rows), its
  // parent.
  std::vector<int> number(nf, -1);
  for (int f = 0; f < nf; ++f)
    if (into[f] == f) number[f] = static_cast<int>(tree.parent.size()), tree.parent.push_back(-1);
  std::vector<std::vector<int>> columns(tree.parent.size());
  for (int f = 0; f < nf; ++f)
    for (int q = start[fundamental[f]]; q < start[fundamental[f + 1]]; ++q)
      columns[number[into[f]]].push_back(q);
  tree.columnStart.push_back(0);
  tree.rowStart.push_back(0);
  for (int f = 0; f < nf; ++f) {
    if (into[f] != f) continue;
    const int s = number[f];
    tree.columns.insert(tree.columns.end(), columns[s].begin(), columns[s].end());
    tree.columnStart.push_back(static_cast<int>(tree.columns.size()));
    for (int i : structure[fundamental[f + 1] - 1])
      tree.rows.insert(tree.rows.end(), tree.order.begin() + start[i],
                       tree.order.begin() + start[i + 1]);
    tree.rowStart.push_back(static_cast<int>(tree.rows.size()));
    tree.parent[s] = fundamentalParent[f] < 0 ? -1 : number[into[fundamentalParent[f]]];
  }
  return tree;
}

}  // namespace gaitopt::ocp::kkt
