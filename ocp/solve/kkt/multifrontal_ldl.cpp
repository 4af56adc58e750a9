#include "ocp/solve/kkt/multifrontal_ldl.hpp"

#include <algorithm>
#include <cmath>

#include "ocp/solve/kkt/front_ldl.hpp"

namespace gaitopt::ocp::kkt {

MultifrontalLdl::MultifrontalLdl(const SymmetricPattern& pattern, const EliminationOrder& order,
                                 int mergeBelow)
    : pattern_(pattern),
      tree_(analyseAssemblyTree(pattern, order, mergeBelow)),
      columnOf_(pattern.nonZeros()),
      children_(tree_.supernodes()),
      factors_(tree_.supernodes()),
      place_(pattern.n, -1),
      stackStart_(tree_.supernodes()) {
  for (int c = 0; c < pattern.n; ++c)
    for (int k = pattern.outer[c]; k < pattern.outer[c + 1]; ++k) columnOf_[k] = c;
  for (int s = 0; s < tree_.supernodes(); ++s)
    if (tree_.parent[s] >= 0) children_[tree_.parent[s]].push_back(s);
}

// Ruiz's (2001) symmetric equilibration in the infinity norm: S = diag(s), each pass dividing
// every row and column by the square root of its largest entry, brings each row's largest
// entry of S A S near 1. Ipopt's matrices span twenty decades (Sigma from 1e-11 to 1e15 near a
// solution); unscaled, a well-posed block of entries near 1 has pivots that a test relative to
// the largest entry takes for zero, and whose digits the threshold test cannot protect. MUMPS,
// as Ipopt calls it, scales too (ICNTL(8) = 77).
void MultifrontalLdl::equilibrate(const double* values) {
  scale_.assign(pattern_.n, 1.0);
  scaled_.assign(values, values + pattern_.nonZeros());
  std::vector<double> largest(pattern_.n);
  for (int pass = 0; pass < kEquilibrationPasses; ++pass) {
    std::fill(largest.begin(), largest.end(), 0.0);
    for (int k = 0; k < pattern_.nonZeros(); ++k) {
      const double v = std::abs(scaled_[k]);
      largest[pattern_.inner[k]] = std::max(largest[pattern_.inner[k]], v);
      largest[columnOf_[k]] = std::max(largest[columnOf_[k]], v);
    }
    for (double& l : largest) l = l > 0 ? 1.0 / std::sqrt(l) : 1.0;
    for (int i = 0; i < pattern_.n; ++i) scale_[i] *= largest[i];
    for (int k = 0; k < pattern_.nonZeros(); ++k)
      scaled_[k] *= largest[pattern_.inner[k]] * largest[columnOf_[k]];
  }
}

void MultifrontalLdl::factorize(const double* values, const PivotTest& test) {
  equilibrate(values);
  double largest = 0;
  for (double v : scaled_) largest = std::max(largest, std::abs(v));
  const PivotTest scaledTest{test.threshold, test.tiny * largest};
  negative_ = perturbed_ = delayed_ = 0;
  stackTop_ = 0;
  for (int s = 0; s < tree_.supernodes(); ++s) factorizeFront(s, scaled_.data(), scaledTest);
}

// The front's rows: its own columns, the rows its children delayed, then L's rows below it.
// Sums A's entries of its own columns and its children's contribution blocks (the delayed rows'
// read in place, the rest from the stack) into its panel and below_ (the fully summed block
// whole, the rest by its lower triangle); returns the fully summed count.
int MultifrontalLdl::assemble(int s, const double* values) {
  FrontFactor& front = factors_[s];
  std::vector<int>& rows = front.rows;
  const auto own = tree_.columns.begin();
  rows.clear();
  for (auto j = own + tree_.columnStart[s]; j != own + tree_.columnStart[s + 1]; ++j)
    rows.push_back(tree_.order[*j]);
  for (int c : children_[s]) {
    const FrontFactor& child = factors_[c];
    rows.insert(rows.end(), child.rows.begin() + child.pivots,
                child.rows.begin() + child.fullySummed);
  }
  const int fullySummed = static_cast<int>(rows.size());
  rows.insert(rows.end(), tree_.rows.begin() + tree_.rowStart[s],
              tree_.rows.begin() + tree_.rowStart[s + 1]);
  const int m = static_cast<int>(rows.size()), nb = m - fullySummed;
  for (int i = 0; i < m; ++i) place_[rows[i]] = i;
  Eigen::MatrixXd& panel = front.matrix;
  panel.resize(m, fullySummed);
  if (below_.size() < static_cast<size_t>(nb) * nb) below_.resize(static_cast<size_t>(nb) * nb);
  Eigen::Map<Eigen::MatrixXd> below(below_.data(), nb, nb);
  diagonal_.resize(m);
  for (int j = 0; j < fullySummed; ++j) diagonal_[j] = panel.col(j).data() + j;
  for (int j = 0; j < nb; ++j) diagonal_[fullySummed + j] = below.col(j).data() + j;
  for (int j = 0; j < m; ++j) std::fill_n(diagonal_[j], m - j, 0.0);  // the lower triangle
  auto add = [this](int a, int b, double v) {
    const int i = std::max(a, b), j = std::min(a, b);
    diagonal_[j][i - j] += v;
  };
  for (auto j = own + tree_.columnStart[s]; j != own + tree_.columnStart[s + 1]; ++j)
    for (int q = tree_.entryStart[*j]; q < tree_.entryStart[*j + 1]; ++q) {
      const int k = tree_.entries[q];
      add(place_[pattern_.inner[k]], place_[columnOf_[k]], values[k]);
    }
  for (int c : children_[s]) {
    const FrontFactor& child = factors_[c];
    const int mc = static_cast<int>(child.rows.size());
    childPlace_.resize(mc);
    for (int i = child.pivots; i < mc; ++i) childPlace_[i] = place_[child.rows[i]];
    // In the parent's order (as a child that delayed no row is), a child's column lands in one
    // column of the parent.
    const bool inOrder = std::is_sorted(childPlace_.begin() + child.pivots, childPlace_.end());
    const double* packed = stack_.data() + stackStart_[c];
    for (int j = child.pivots; j < mc; ++j) {
      const int b = childPlace_[j];
      // The child's column j from its diagonal down.
      const double* v = packed;
      if (j < child.fullySummed)
        v = child.matrix.col(j).data() + j;
      else
        packed += mc - j;
      if (inOrder) {
        double* column = diagonal_[b];
        for (int i = j; i < mc; ++i) column[childPlace_[i] - b] += v[i - j];
      } else {
        for (int i = j; i < mc; ++i) add(childPlace_[i], b, v[i - j]);
      }
    }
  }
  auto summed = panel.topLeftCorner(fullySummed, fullySummed);
  summed.triangularView<Eigen::StrictlyUpper>() = summed.transpose();
  return fullySummed;
}

void MultifrontalLdl::factorizeFront(int s, const double* values, const PivotTest& test) {
  FrontFactor& front = factors_[s];
  front.fullySummed = assemble(s, values);
  const int nb = static_cast<int>(front.rows.size()) - front.fullySummed;
  factorFront(front.matrix, Eigen::Map<Eigen::MatrixXd>(below_.data(), nb, nb), tree_.parent[s] < 0,
              test, pivots_, workspace_);
  permuted_.resize(front.rows.size());
  for (size_t i = 0; i < front.rows.size(); ++i) permuted_[i] = front.rows[pivots_.permutation[i]];
  front.rows.swap(permuted_);
  front.pivots = pivots_.pivots;
  front.inverseDiagonal.swap(pivots_.inverseDiagonal);
  front.inverseOffDiagonal.swap(pivots_.inverseOffDiagonal);
  negative_ += pivots_.negative;
  perturbed_ += pivots_.perturbed;
  delayed_ += front.fullySummed - front.pivots;
  pushContribution(s, nb);
}

// The supernodes come in postorder, so the children's blocks are the top of the stack when
// their parent is assembled; the parent's replaces them. Only a block's lower triangle is kept:
// keeping every front whole outgrew the caches (the ensemble's 2 200 fronts held 350 MB).
void MultifrontalLdl::pushContribution(int s, int rows) {
  if (!children_[s].empty()) stackTop_ = stackStart_[children_[s].front()];
  stackStart_[s] = stackTop_;
  const size_t size = static_cast<size_t>(rows) * (rows + 1) / 2;
  if (stack_.size() < stackTop_ + size) stack_.resize(stackTop_ + size);
  double* out = stack_.data() + stackTop_;
  const Eigen::Map<const Eigen::MatrixXd> below(below_.data(), rows, rows);
  for (int j = 0; j < rows; ++j) out = std::copy_n(below.col(j).data() + j, rows - j, out);
  stackTop_ += size;
}

void MultifrontalLdl::solve(double* x) const {
  for (int i = 0; i < pattern_.n; ++i) x[i] *= scale_[i];  // A^{-1} = S (S A S)^{-1} S
  const int nf = tree_.supernodes();
  for (int s = 0; s < nf; ++s) {  // L y = x, front by front
    const FrontFactor& f = factors_[s];
    const int np = f.pivots, below = static_cast<int>(f.rows.size()) - np;
    work_.resize(f.rows.size());
    Eigen::Map<Eigen::VectorXd> y(work_.data(), np), z(work_.data() + np, below);
    for (int i = 0; i < np; ++i) y[i] = x[f.rows[i]];
    f.matrix.topLeftCorner(np, np).triangularView<Eigen::UnitLower>().solveInPlace(y);
    z.noalias() = f.matrix.bottomLeftCorner(below, np) * y;
    for (int i = 0; i < np; ++i) x[f.rows[i]] = y[i];
    for (int i = 0; i < below; ++i) x[f.rows[np + i]] -= z[i];
  }
  for (const FrontFactor& f : factors_) {  // D z = y
    for (int i = 0; i < f.pivots; ++i) {
      const double off = f.inverseOffDiagonal[i];
      if (off == 0.0) {
        x[f.rows[i]] *= f.inverseDiagonal[i];
        continue;
      }
      const double a = x[f.rows[i]], b = x[f.rows[i + 1]];
      x[f.rows[i]] = f.inverseDiagonal[i] * a + off * b;
      x[f.rows[i + 1]] = off * a + f.inverseDiagonal[i + 1] * b;
      ++i;
    }
  }
  for (int s = nf - 1; s >= 0; --s) {  // L^T x = z
    const FrontFactor& f = factors_[s];
    const int np = f.pivots, below = static_cast<int>(f.rows.size()) - np;
    work_.resize(f.rows.size());
    Eigen::Map<Eigen::VectorXd> y(work_.data(), np), z(work_.data() + np, below);
    for (int i = 0; i < np; ++i) y[i] = x[f.rows[i]];
    for (int i = 0; i < below; ++i) z[i] = x[f.rows[np + i]];
    y.noalias() -= f.matrix.bottomLeftCorner(below, np).transpose() * z;
    f.matrix.topLeftCorner(np, np).triangularView<Eigen::UnitLower>().transpose().solveInPlace(y);
    for (int i = 0; i < np; ++i) x[f.rows[i]] = y[i];
  }
  for (int i = 0; i < pattern_.n; ++i) x[i] *= scale_[i];
}

}  // namespace gaitopt::ocp::kkt
