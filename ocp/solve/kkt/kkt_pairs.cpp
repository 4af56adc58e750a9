#include "ocp/solve/kkt/kkt_pairs.hpp"

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

/// Kuhn's augmenting paths on the bipartite graph variable rows <-> constraint rows, each row's
/// neighbours across the split in CSR arrays, strongest coupling first.
class Matching {
 public:
  Matching(const SymmetricPattern& pattern, const double* values, int constraintStart)
      : start_(pattern.n + 1, 0), mate_(pattern.n, -1), seen_(pattern.n, -1) {
    auto across = [&](int r, int c, int k) {
      return (r < constraintStart) != (c < constraintStart) && values[k] != 0.0;
    };
    for (int c = 0; c < pattern.n; ++c)
      for (int k = pattern.outer[c]; k < pattern.outer[c + 1]; ++k)
        if (across(pattern.inner[k], c, k)) ++start_[pattern.inner[k] + 1], ++start_[c + 1];
    for (int i = 0; i < pattern.n; ++i) start_[i + 1] += start_[i];
    std::vector<std::pair<double, int>> weighted(start_[pattern.n]);
    std::vector<int> next(start_.begin(), start_.end() - 1);
    for (int c = 0; c < pattern.n; ++c) {
      for (int k = pattern.outer[c]; k < pattern.outer[c + 1]; ++k) {
        const int r = pattern.inner[k];
        if (!across(r, c, k)) continue;
        weighted[next[r]++] = {-std::abs(values[k]), c};
        weighted[next[c]++] = {-std::abs(values[k]), r};
      }
    }
    neighbour_.resize(weighted.size());
    for (int i = 0; i < pattern.n; ++i) {
      std::sort(weighted.begin() + start_[i], weighted.begin() + start_[i + 1]);
      for (int q = start_[i]; q < start_[i + 1]; ++q) neighbour_[q] = weighted[q].second;
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
    for (int q = start_[u]; q < start_[u + 1]; ++q) {
      const int v = neighbour_[q];
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

  std::vector<int> start_, neighbour_;  // neighbours across the split, strongest first
  std::vector<int> mate_, seen_;
  int stamp_ = 0;
};

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
