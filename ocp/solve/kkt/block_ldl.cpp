#include "ocp/solve/kkt/block_ldl.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace gaitopt::ocp::kkt {

BlockLdl::BlockLdl(const SymmetricPattern& pattern, const EliminationOrder& order) {
  formBlocks(pattern.n, order);
  scatterPattern(pattern);
  eliminationTree();
}

// One block per node of the order, eliminated in the order's sequence.
void BlockLdl::formBlocks(int n, const EliminationOrder& order) {
  blockOf_ = order.nodeOfRows(n);
  offsetOf_.assign(n, 0);
  for (size_t k = 0; k + 1 < order.nodeStart.size(); ++k) {
    const int first = order.nodeStart[k], size = order.nodeStart[k + 1] - first;
    if (size > 2) throw std::invalid_argument("BlockLdl: nodes of one or two rows");
    first_.push_back(order.rows[first]);
    second_.push_back(size == 2 ? order.rows[first + 1] : -1);
    if (size == 2) offsetOf_[second_.back()] = 1;
  }
}

// The upper block triangle of P A P^T, column by column (the diagonal block first, other rows
// unsorted), and where each entry of A goes in it (column-major 2x2 elements: element = row +
// 2 col). A counting sort by block column and a marker per column: linear in the entries.
void BlockLdl::scatterPattern(const SymmetricPattern& pattern) {
  const int nb = blocks(), nnz = pattern.nonZeros();
  struct Placed {
    int row, column, element, mirror;
  };
  std::vector<Placed> placed(nnz);
  std::vector<int> start(nb + 1, 0);
  for (int c = 0; c < pattern.n; ++c) {
    for (int k = pattern.outer[c]; k < pattern.outer[c + 1]; ++k) {
      const int r = pattern.inner[k];
      // A(r, c) sits in block (row, col), row <= col, at (its row's place, the other's).
      const int pr = blockOf_[r], pc = blockOf_[c];
      const int er = pr <= pc ? offsetOf_[r] : offsetOf_[c];
      const int ec = pr <= pc ? offsetOf_[c] : offsetOf_[r];
      const int mirror = pr == pc && er != ec ? ec + 2 * er : -1;
      placed[k] = {std::min(pr, pc), std::max(pr, pc), er + 2 * ec, mirror};
      ++start[placed[k].column + 1];
    }
  }
  for (int b = 0; b < nb; ++b) start[b + 1] += start[b];
  std::vector<int> byColumn(nnz), next(start.begin(), start.end() - 1);
  for (int k = 0; k < nnz; ++k) byColumn[next[placed[k].column]++] = k;
  std::vector<int> mark(nb, -1), slotOfRow(nb);
  cp_.assign(nb + 1, 0);
  ci_.clear();
  ci_.reserve(nnz + nb);
  scatter_.assign(nnz, {});
  auto store = [&](int row, int col) {
    if (mark[row] == col) return;
    mark[row] = col;
    slotOfRow[row] = static_cast<int>(ci_.size());
    ci_.push_back(row);
  };
  for (int col = 0; col < nb; ++col) {
    cp_[col] = static_cast<int>(ci_.size());
    store(col, col);  // every pivot has its diagonal block
    for (int q = start[col]; q < start[col + 1]; ++q) {
      const Placed& e = placed[byColumn[q]];
      store(e.row, col);
      scatter_[byColumn[q]] = {byColumn[q], slotOfRow[e.row], e.element, e.mirror};
    }
  }
  cp_[nb] = static_cast<int>(ci_.size());
  cx_.assign(ci_.size(), Mat2::Zero());
}

// Elimination tree, column counts (ldl_symbolic on blocks) and the nonzero pattern of every
// block row of L in topological order (the reach of a sparse triangular solve), which is the
// same for every factorization.
void BlockLdl::eliminationTree() {
  const int nb = blocks();
  parent_.assign(nb, -1);
  lnz_.assign(nb, 0);
  std::vector<int> flag(nb, -1), stack(nb);
  rowStart_.assign(nb + 1, 0);
  rowBlocks_.clear();
  for (int k = 0; k < nb; ++k) {
    flag[k] = k;
    int top = nb;
    for (int p = cp_[k]; p < cp_[k + 1]; ++p) {
      int len = 0;
      for (int i = ci_[p]; i < k && flag[i] != k; i = parent_[i]) {
        if (parent_[i] == -1) parent_[i] = k;
        ++lnz_[i];
        flag[i] = k;
        stack[len++] = i;
      }
      while (len > 0) stack[--top] = stack[--len];
    }
    rowBlocks_.insert(rowBlocks_.end(), stack.begin() + top, stack.end());
    rowStart_[k + 1] = static_cast<int>(rowBlocks_.size());
  }
  lp_.assign(nb + 1, 0);
  for (int k = 0; k < nb; ++k) lp_[k + 1] = lp_[k] + lnz_[k];
  li_.resize(lp_[nb]);
  lx_.resize(lp_[nb]);
  dinv_.resize(nb);
  y_.assign(nb, Mat2::Zero());
}

void BlockLdl::factorize(const double* values, double tiny) {
  std::fill(cx_.begin(), cx_.end(), Mat2::Zero());
  for (const Scatter& s : scatter_) {
    cx_[s.slot].data()[s.element] = values[s.entry];
    if (s.mirror >= 0) cx_[s.slot].data()[s.mirror] = values[s.entry];
  }
  std::fill(lnz_.begin(), lnz_.end(), 0);
  negative_ = perturbed_ = 0;
  for (int k = 0; k < blocks(); ++k) eliminateBlockRow(k, tiny);
}

// Up-looking step for block row k: scatter block column k of A into y_, then in topological
// order W_i = (D L^T)_{ik} (a sparse triangular solve), L_ki = W_i^T D_i^{-1},
// D_k = A_kk - sum_i L_ki W_i.
void BlockLdl::eliminateBlockRow(int k, double tiny) {
  for (int p = cp_[k]; p < cp_[k + 1]; ++p) y_[ci_[p]] += cx_[p];
  Mat2 d = y_[k];
  y_[k].setZero();
  for (int r = rowStart_[k]; r < rowStart_[k + 1]; ++r) {
    const int i = rowBlocks_[r];
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
  std::vector<Vec2>& y = solution_;
  y.resize(nb);
  for (int k = 0; k < nb; ++k) y[k] = Vec2(x[first_[k]], second_[k] >= 0 ? x[second_[k]] : 0.0);
  for (int j = 0; j < nb; ++j)
    for (int p = lp_[j]; p < lp_[j + 1]; ++p) y[li_[p]].noalias() -= lx_[p] * y[j];
  for (int j = 0; j < nb; ++j) y[j] = dinv_[j] * y[j];
  for (int j = nb - 1; j >= 0; --j)
    for (int p = lp_[j]; p < lp_[j + 1]; ++p) y[j].noalias() -= lx_[p].transpose() * y[li_[p]];
  for (int k = 0; k < nb; ++k) {
    x[first_[k]] = y[k][0];
    if (second_[k] >= 0) x[second_[k]] = y[k][1];
  }
}

}  // namespace gaitopt::ocp::kkt
