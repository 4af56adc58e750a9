#include "ocp/kkt/kkt_pairs.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace gaitopt::ocp::kkt {

int constraintRowsStart(const SymmetricPattern& pattern) {
  // Walk left while column j couples only to rows before the candidate block start.
  int start = pattern.n;
  for (int j = pattern.n - 1; j >= 0; --j) {
    for (int k = pattern.outer[j]; k < pattern.outer[j + 1]; ++k)
      if (pattern.inner[k] != j && pattern.inner[k] >= start) return start;
    start = j;
  }
  return start;
}

std::vector<int> zeroDiagonalVariables(const SymmetricPattern& pattern, const double* values,
                                       int constraintStart) {
  std::vector<int> rows;
  for (int j = 0; j < constraintStart; ++j)
    if (values[pattern.diagonal[j]] == 0.0) rows.push_back(j);
  return rows;
}

namespace {

/// Kuhn's augmenting paths on the bipartite graph variable rows <-> constraint rows.
class Matching {
 public:
  Matching(const SymmetricPattern& pattern, const double* values, int constraintStart)
      : across_(pattern.n), mate_(pattern.n, -1), seen_(pattern.n, -1) {
    std::vector<std::vector<std::pair<double, int>>> weighted(pattern.n);
    for (int c = 0; c < pattern.n; ++c) {
      for (int k = pattern.outer[c]; k < pattern.outer[c + 1]; ++k) {
        const int r = pattern.inner[k];
        if ((r < constraintStart) == (c < constraintStart) || values[k] == 0.0) continue;
        weighted[r].emplace_back(-std::abs(values[k]), c);
        weighted[c].emplace_back(-std::abs(values[k]), r);
      }
    }
    for (int i = 0; i < pattern.n; ++i) {
      std::sort(weighted[i].begin(), weighted[i].end());
      for (const auto& [weight, j] : weighted[i]) across_[i].push_back(j);
    }
  }

  void augmentFrom(int row) {
    if (mate_[row] >= 0) return;
    ++stamp_;
    tryRow(row);
  }
  int mate(int row) const { return mate_[row]; }

 private:
  bool tryRow(int u) {
    for (int v : across_[u]) {
      if (seen_[v] == stamp_) continue;
      seen_[v] = stamp_;
      if (mate_[v] < 0 || tryRow(mate_[v])) {
        mate_[v] = u;
        mate_[u] = v;
        return true;
      }
    }
    return false;
  }

  std::vector<std::vector<int>> across_;  // neighbours across the split, strongest first
  std::vector<int> mate_, seen_;
  int stamp_ = 0;
};

}  // namespace

namespace {

/// The strongest still unpaired neighbour of `row` on either side (-1 if none).
int strongestFreeNeighbour(const SymmetricPattern& pattern, const double* values, int row,
                           const std::vector<int>& mate) {
  int best = -1;
  double strongest = 0;
  auto consider = [&](int other, double value) {
    if (other == row || mate[other] >= 0 || std::abs(value) <= strongest) return;
    strongest = std::abs(value);
    best = other;
  };
  for (int k = pattern.outer[row]; k < pattern.outer[row + 1]; ++k)
    consider(pattern.inner[k], values[k]);
  for (int c = 0; c < row; ++c)  // the entries of row `row` left of the diagonal
    for (int k = pattern.outer[c]; k < pattern.outer[c + 1]; ++k)
      if (pattern.inner[k] == row) consider(c, values[k]);
  return best;
}

}  // namespace

std::vector<PivotPair> kktPivotPairs(const SymmetricPattern& pattern, const double* values,
                                     int constraintStart, const std::vector<int>& mustPair) {
  Matching matching(pattern, values, constraintStart);
  for (int row : mustPair) matching.augmentFrom(row);
  for (int row = constraintStart; row < pattern.n; ++row) matching.augmentFrom(row);
  std::vector<int> mate(pattern.n);
  for (int row = 0; row < pattern.n; ++row) mate[row] = matching.mate(row);
  // A variable row the constraints could not take pairs with a free variable it couples to
  // through W: [0 w; w d] is as good a pivot as a constraint pair.
  for (int row : mustPair) {
    if (mate[row] >= 0) continue;
    const int other = strongestFreeNeighbour(pattern, values, row, mate);
    if (other < 0) continue;
    mate[row] = other;
    mate[other] = row;
  }
  std::vector<PivotPair> pairs;
  for (int row = 0; row < pattern.n; ++row)
    if (mate[row] > row) pairs.push_back({row, mate[row]});
  return pairs;
}

}  // namespace gaitopt::ocp::kkt
