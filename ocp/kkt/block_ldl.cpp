#include "ocp/kkt/block_ldl.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/OrderingMethods>
#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace gaitopt::ocp::kkt {

BlockLdl::BlockLdl(const SymmetricPattern& pattern, const std::vector<PivotPair>& pairs) {
  formBlocks(pattern.n, pairs);
  orderBlocks(pattern);
  scatterPattern(pattern);
  eliminationTree();
}

void BlockLdl::formBlocks(int n, const std::vector<PivotPair>& pairs) {
  blockOf_.assign(n, -1);
  offsetOf_.assign(n, 0);
  for (const PivotPair& p : pairs) {
    if (p.first == p.second || blockOf_[p.first] >= 0 || blockOf_[p.second] >= 0)
      throw std::invalid_argument("BlockLdl: pivot pairs must be disjoint pairs of rows");
    blockOf_[p.first] = blockOf_[p.second] = static_cast<int>(first_.size());
    offsetOf_[p.second] = 1;
    first_.push_back(p.first);
    second_.push_back(p.second);
  }
  for (int i = 0; i < n; ++i) {
    if (blockOf_[i] >= 0) continue;
    blockOf_[i] = static_cast<int>(first_.size());
    first_.push_back(i);
    second_.push_back(-1);
  }
}

// Approximate minimum degree on the graph of the blocks (Eigen's port of AMD).
void BlockLdl::orderBlocks(const SymmetricPattern& pattern) {
  const int nb = blocks();
  std::vector<Eigen::Triplet<double, int>> edges;
  edges.reserve(2 * pattern.nonZeros() + nb);
  for (int c = 0; c < pattern.n; ++c) {
    for (int k = pattern.outer[c]; k < pattern.outer[c + 1]; ++k) {
      edges.emplace_back(blockOf_[pattern.inner[k]], blockOf_[c], 1.0);
      edges.emplace_back(blockOf_[c], blockOf_[pattern.inner[k]], 1.0);
    }
  }
  Eigen::SparseMatrix<double, Eigen::ColMajor, int> graph(nb, nb);
  graph.setFromTriplets(edges.begin(), edges.end());
  Eigen::PermutationMatrix<Eigen::Dynamic, Eigen::Dynamic, int> perm;
  Eigen::AMDOrdering<int>()(graph, perm);
  order_.assign(perm.indices().data(), perm.indices().data() + nb);
  position_.assign(nb, 0);
  for (int k = 0; k < nb; ++k) position_[order_[k]] = k;
}

// The upper block triangle of P A P^T, column by column, and where each entry of A goes in it
// (column-major 2x2 elements: element = row + 2 col).
void BlockLdl::scatterPattern(const SymmetricPattern& pattern) {
  const int nb = blocks();
  std::vector<std::vector<int>> columns(nb);
  for (int b = 0; b < nb; ++b) columns[b].push_back(b);
  auto place = [&](int r, int c) {
    const int pr = position_[blockOf_[r]], pc = position_[blockOf_[c]];
    return std::pair{std::min(pr, pc), std::max(pr, pc)};
  };
  for (int c = 0; c < pattern.n; ++c) {
    for (int k = pattern.outer[c]; k < pattern.outer[c + 1]; ++k) {
      const auto [row, col] = place(pattern.inner[k], c);
      columns[col].push_back(row);
    }
  }
  cp_.assign(nb + 1, 0);
  for (int b = 0; b < nb; ++b) {
    std::sort(columns[b].begin(), columns[b].end());
    columns[b].erase(std::unique(columns[b].begin(), columns[b].end()), columns[b].end());
    cp_[b + 1] = cp_[b] + static_cast<int>(columns[b].size());
  }
  ci_.clear();
  for (const auto& column : columns) ci_.insert(ci_.end(), column.begin(), column.end());
  scatter_.clear();
  for (int c = 0; c < pattern.n; ++c) {
    for (int k = pattern.outer[c]; k < pattern.outer[c + 1]; ++k) {
      const int r = pattern.inner[k];
      const auto [row, col] = place(r, c);
      const int slot = static_cast<int>(
          std::lower_bound(ci_.begin() + cp_[col], ci_.begin() + cp_[col + 1], row) - ci_.begin());
      // Entry A(r, c) sits in block (row, col) at (offset of the row-block's row, other).
      const bool rowFirst = position_[blockOf_[r]] <= position_[blockOf_[c]];
      const int er = rowFirst ? offsetOf_[r] : offsetOf_[c];
      const int ec = rowFirst ? offsetOf_[c] : offsetOf_[r];
      const bool inDiagonalBlock = row == col && er != ec;
      scatter_.push_back({k, slot, er + 2 * ec, inDiagonalBlock ? ec + 2 * er : -1});
    }
  }
  cx_.assign(ci_.size(), Mat2::Zero());
}

// Elimination tree and column counts of the block factor (ldl_symbolic on blocks).
void BlockLdl::eliminationTree() {
  const int nb = blocks();
  parent_.assign(nb, -1);
  lnz_.assign(nb, 0);
  flag_.assign(nb, -1);
  for (int k = 0; k < nb; ++k) {
    flag_[k] = k;
    for (int p = cp_[k]; p < cp_[k + 1]; ++p) {
      for (int i = ci_[p]; i < k && flag_[i] != k; i = parent_[i]) {
        if (parent_[i] == -1) parent_[i] = k;
        ++lnz_[i];
        flag_[i] = k;
      }
    }
  }
  lp_.assign(nb + 1, 0);
  for (int k = 0; k < nb; ++k) lp_[k + 1] = lp_[k] + lnz_[k];
  li_.resize(lp_[nb]);
  lx_.resize(lp_[nb]);
  dinv_.resize(nb);
  y_.assign(nb, Mat2::Zero());
  pattern_.resize(nb);
}

void BlockLdl::factorize(const double* values, double tiny) {
  std::fill(cx_.begin(), cx_.end(), Mat2::Zero());
  for (const Scatter& s : scatter_) {
    cx_[s.slot].data()[s.element] = values[s.entry];
    if (s.mirror >= 0) cx_[s.slot].data()[s.mirror] = values[s.entry];
  }
  std::fill(flag_.begin(), flag_.end(), -1);
  negative_ = perturbed_ = 0;
  perturbedRows_.clear();
  for (int k = 0; k < blocks(); ++k) eliminateBlockRow(k, tiny);
}

// Scatters block column k of the upper pattern into y_ and returns where the nonzero pattern of
// block row k of L starts in pattern_ (topological order: a sparse triangular solve's reach).
int BlockLdl::rowPattern(int k) {
  const int nb = blocks();
  int top = nb;
  y_[k].setZero();
  flag_[k] = k;
  lnz_[k] = 0;
  for (int p = cp_[k]; p < cp_[k + 1]; ++p) {
    int i = ci_[p];
    y_[i] += cx_[p];
    int len = 0;
    for (; flag_[i] != k; i = parent_[i]) {
      pattern_[len++] = i;
      flag_[i] = k;
    }
    while (len > 0) pattern_[--top] = pattern_[--len];
  }
  return top;
}

// Up-looking step: W_i = (D L^T)_{ik} by a sparse triangular solve, L_ki = W_i^T D_i^{-1},
// D_k = A_kk - sum_i L_ki W_i.
void BlockLdl::eliminateBlockRow(int k, double tiny) {
  const int nb = blocks();
  const int start = rowPattern(k);
  Mat2 d = y_[k];
  y_[k].setZero();
  for (int top = start; top < nb; ++top) {
    const int i = pattern_[top];
    const Mat2 w = y_[i];
    y_[i].setZero();
    const int end = lp_[i] + lnz_[i];
    for (int p = lp_[i]; p < end; ++p) y_[li_[p]].noalias() -= lx_[p] * w;
    const Mat2 l = w.transpose() * dinv_[i];
    d.noalias() -= l * w;
    li_[end] = k;
    lx_[end] = l;
    ++lnz_[i];
  }
  pivot(k, d, tiny);
}

// D_k^{-1} of a 1x1 pivot (the block's (0, 0) element; the rest of its block stays zero) or of
// a 2x2 pivot [a b; b c] as adj / det: its eigenvalues have product det and sum a + c, and the
// small one, det / (the large one), keeps its digits where an eigen solver's would cancel. Only
// a pivot with an eigenvalue below `tiny` goes through the eigen decomposition, to be clamped.
void BlockLdl::pivot(int k, Mat2 d, double tiny) {
  auto clamp = [&](double lambda) {
    if (std::abs(lambda) < tiny) {
      ++perturbed_;
      perturbedRows_.push_back(first_[order_[k]]);
      lambda = lambda < 0 ? -tiny : tiny;
    }
    if (lambda < 0) ++negative_;
    return lambda;
  };
  dinv_[k].setZero();
  if (single(k)) {
    dinv_[k](0, 0) = 1.0 / clamp(d(0, 0));
    return;
  }
  const double a = d(0, 0), c = d(1, 1), b = 0.5 * (d(0, 1) + d(1, 0));
  const double det = std::fma(a, c, -b * b);
  const double large = std::abs(0.5 * (a + c)) + std::hypot(0.5 * (a - c), b);
  if (large > 0 && std::abs(det) >= tiny * large) {
    clamp(det < 0 ? -large : std::copysign(large, a + c));
    clamp(det / (det < 0 ? -large : std::copysign(large, a + c)));
    dinv_[k] << c / det, -b / det, -b / det, a / det;
    return;
  }
  d(0, 1) = d(1, 0) = b;
  Eigen::SelfAdjointEigenSolver<Mat2> eigen;
  eigen.computeDirect(d);
  const Vec2 inverse(1.0 / clamp(eigen.eigenvalues()[0]), 1.0 / clamp(eigen.eigenvalues()[1]));
  dinv_[k] = eigen.eigenvectors() * inverse.asDiagonal() * eigen.eigenvectors().transpose();
}

void BlockLdl::solve(double* x) const {
  const int nb = blocks();
  std::vector<Vec2> y(nb);
  for (int k = 0; k < nb; ++k) {
    const int b = order_[k];
    y[k] = Vec2(x[first_[b]], second_[b] >= 0 ? x[second_[b]] : 0.0);
  }
  for (int j = 0; j < nb; ++j)
    for (int p = lp_[j]; p < lp_[j + 1]; ++p) y[li_[p]].noalias() -= lx_[p] * y[j];
  for (int j = 0; j < nb; ++j) y[j] = dinv_[j] * y[j];
  for (int j = nb - 1; j >= 0; --j)
    for (int p = lp_[j]; p < lp_[j + 1]; ++p) y[j].noalias() -= lx_[p].transpose() * y[li_[p]];
  for (int k = 0; k < nb; ++k) {
    const int b = order_[k];
    x[first_[b]] = y[k][0];
    if (second_[b] >= 0) x[second_[b]] = y[k][1];
  }
}

}  // namespace gaitopt::ocp::kkt
