#include "ocp/solve/kkt/front_ldl.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <numeric>
#include <utility>

namespace gaitopt::ocp::kkt {

namespace {

/// Bunch and Kaufman's (1977) alpha, (1 + sqrt(17)) / 8: it minimises the growth bound.
const double kBunchKaufmanAlpha = (1.0 + std::sqrt(17.0)) / 8.0;

/// The largest |x[i]| (0 if none), NaNs passed over. The largest of a set is the same in any
/// order, so four running maxima hide the comparison's latency without changing a bit.
double largestMagnitude(const double* x, int n) {
  double m0 = 0, m1 = 0, m2 = 0, m3 = 0;
  int i = 0;
  for (; i + 4 <= n; i += 4) {
    m0 = std::max(m0, std::abs(x[i]));
    m1 = std::max(m1, std::abs(x[i + 1]));
    m2 = std::max(m2, std::abs(x[i + 2]));
    m3 = std::max(m3, std::abs(x[i + 3]));
  }
  for (; i < n; ++i) m0 = std::max(m0, std::abs(x[i]));
  return std::max(std::max(m0, m1), std::max(m2, m3));
}

/// A pivot: row j alone, or rows j and r as a 2x2 block (r = -1 for a 1x1 pivot).
struct Choice {
  int j = -1;
  int r = -1;
};

class Front {
 public:
  Front(Eigen::Ref<Eigen::MatrixXd> panel, Eigen::Ref<Eigen::MatrixXd> below, const PivotTest& test,
        FrontPivots& result, Eigen::MatrixXd& workspace)
      : f_(panel),
        below_(below),
        m_(static_cast<int>(panel.rows())),
        p_(static_cast<int>(panel.cols())),
        u_(test.threshold),
        tiny_(test.tiny),
        w_(workspace),
        result_(result) {
    w_.resize(m_ - p_, p_);
    result_.permutation.resize(m_);
    std::iota(result_.permutation.begin(), result_.permutation.end(), 0);
    result_.inverseDiagonal.clear();
    result_.inverseOffDiagonal.clear();
    result_.negative = result_.perturbed = 0;
  }

  void eliminate(bool root) {
    while (k_ < p_) {
      const Choice c = root ? bunchKaufman() : threshold();
      if (c.j < 0) break;  // the remaining fully summed rows are delayed
      swap(k_, c.j);
      if (c.r < 0) {
        pivot1();
      } else {
        swap(k_ + 1, c.r == k_ ? c.j : c.r);
        pivot2();
      }
    }
    result_.pivots = k_;
    updateContribution();
  }

 private:
  /// Largest |f(i, j)| over the active rows i >= k, skipping rows a and b (-1: none).
  double columnMax(int j, int a, int b) const {
    const double* column = f_.col(j).data();
    double largest = 0;
    int from = k_;
    for (int skip : {std::min(a, b), std::max(a, b)}) {
      if (skip < from) continue;
      largest = std::max(largest, largestMagnitude(column + from, skip - from));
      from = skip + 1;
    }
    return std::max(largest, largestMagnitude(column + from, m_ - from));
  }
  /// The fully summed active row other than j with the largest |f(i, j)| (-1 if all are zero).
  int strongestFullySummed(int j) const {
    int best = -1;
    double largest = 0;
    for (int i = k_; i < p_; ++i) {
      if (i == j || std::abs(f_(i, j)) <= largest) continue;
      largest = std::abs(f_(i, j));
      best = i;
    }
    return best;
  }

  Choice threshold() const {
    for (int j = k_; j < p_; ++j) {
      const double ajj = std::abs(f_(j, j));
      if (ajj > tiny_ && ajj >= u_ * columnMax(j, j, -1)) return {j, -1};
      const int r = strongestFullySummed(j);
      if (r >= 0 && acceptable2x2(j, r)) return {j, r};
    }
    return {};
  }

  bool acceptable2x2(int j, int r) const {
    const double a = f_(j, j), b = f_(r, j), c = f_(r, r);
    const double det = a * c - b * b;
    if (std::abs(det) <= tiny_ * (std::abs(a) + std::abs(b) + std::abs(c))) return false;
    const double gj = columnMax(j, j, r), gr = columnMax(r, j, r);
    const double bound = std::abs(det) / u_;
    return std::abs(c) * gj + std::abs(b) * gr <= bound &&
           std::abs(b) * gj + std::abs(a) * gr <= bound;
  }

  /// Bunch-Kaufman on the first active row: a 1x1 pivot on it or on its strongest neighbour r,
  /// else the 2x2 pivot on both.
  Choice bunchKaufman() const {
    const int k = k_;
    const int r = strongestFullySummed(k);
    const double akk = std::abs(f_(k, k));
    const double gamma = r < 0 ? 0.0 : std::abs(f_(r, k));
    if (akk >= kBunchKaufmanAlpha * gamma) return {k, -1};  // includes a zero column
    const double gammaR = columnMax(r, r, -1);
    if (akk * gammaR >= kBunchKaufmanAlpha * gamma * gamma) return {k, -1};
    if (std::abs(f_(r, r)) >= kBunchKaufmanAlpha * gammaR) return {r, -1};
    return {k, r};
  }

  /// Symmetric swap of active fully summed rows a and b: the fully summed block is stored whole,
  /// the rows below it by columns, and L's rows (columns before k) follow their rows.
  void swap(int a, int b) {
    if (a == b) return;
    f_.col(a).swap(f_.col(b));
    f_.row(a).head(p_).swap(f_.row(b).head(p_));
    std::swap(result_.permutation[a], result_.permutation[b]);
  }

  double clamp(double lambda) {
    if (std::abs(lambda) < tiny_) {
      ++result_.perturbed;
      lambda = lambda < 0 ? -tiny_ : tiny_;
    }
    if (lambda < 0) ++result_.negative;
    return lambda;
  }

  void pivot1() {
    const int k = k_, below = m_ - k - 1, panel = p_ - k - 1;
    const double dinv = 1.0 / clamp(f_(k, k));
    w_.col(k) = f_.col(k).tail(m_ - p_);
    f_.block(k + 1, k + 1, below, panel).noalias() -=
        (f_.col(k).tail(below) * dinv) * f_.col(k).segment(k + 1, panel).transpose();
    f_.col(k).tail(below) *= dinv;
    result_.inverseDiagonal.push_back(dinv);
    result_.inverseOffDiagonal.push_back(0.0);
    k_ += 1;
  }

  void pivot2() {
    const int k = k_, below = m_ - k - 2, panel = p_ - k - 2;
    Eigen::Matrix2d d = f_.block<2, 2>(k, k);
    d(0, 1) = d(1, 0) = 0.5 * (d(0, 1) + d(1, 0));
    const Eigen::Matrix2d dinv = inverse(d);
    w_.middleCols<2>(k) = f_.block(p_, k, m_ - p_, 2);
    const Eigen::MatrixXd l = f_.block(k + 2, k, below, 2) * dinv;
    f_.block(k + 2, k + 2, below, panel).noalias() -= l * f_.block(k + 2, k, panel, 2).transpose();
    f_.block(k + 2, k, below, 2) = l;
    f_(k + 1, k) = 0.0;
    result_.inverseDiagonal.insert(result_.inverseDiagonal.end(), {dinv(0, 0), dinv(1, 1)});
    result_.inverseOffDiagonal.insert(result_.inverseOffDiagonal.end(), {dinv(0, 1), 0.0});
    k_ += 2;
  }

  /// The 2x2 pivot's inverse as adj / det, its eigenvalues counted: they have product det and
  /// sum a + c, and the small one, det / (the large one), keeps its digits where an eigen
  /// solver's would cancel. Only a pivot with an eigenvalue below `tiny` goes through the eigen
  /// decomposition, to be clamped.
  Eigen::Matrix2d inverse(const Eigen::Matrix2d& d) {
    const double a = d(0, 0), c = d(1, 1), b = d(0, 1);
    const double det = std::fma(a, c, -b * b);
    const double large = std::abs(0.5 * (a + c)) + std::hypot(0.5 * (a - c), b);
    if (large > 0 && std::abs(det) >= tiny_ * large) {
      const double signedLarge = det < 0 ? -large : std::copysign(large, a + c);
      clamp(signedLarge);
      clamp(det / signedLarge);
      Eigen::Matrix2d inv;
      inv << c / det, -b / det, -b / det, a / det;
      return inv;
    }
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eigen;
    eigen.computeDirect(d);
    const Eigen::Vector2d inv(1.0 / clamp(eigen.eigenvalues()[0]),
                              1.0 / clamp(eigen.eigenvalues()[1]));
    return eigen.eigenvectors() * inv.asDiagonal() * eigen.eigenvectors().transpose();
  }

  /// The rows below the fully summed ones receive their Schur complement in one product:
  /// f(p:, p:) -= L(p:, 0:k) (D L(p:, 0:k)^T), D L^T being the pivot columns kept unscaled.
  void updateContribution() {
    const int below = m_ - p_;
    if (below == 0 || k_ == 0) return;
    below_.triangularView<Eigen::Lower>() -=
        f_.block(p_, 0, below, k_) * w_.leftCols(k_).transpose();
  }

  Eigen::Ref<Eigen::MatrixXd> f_;      // the front's first p columns
  Eigen::Ref<Eigen::MatrixXd> below_;  // f(p:, p:), the rows below the fully summed ones
  int m_, p_;
  double u_, tiny_;
  Eigen::MatrixXd& w_;  // rows below the fully summed ones of D L^T's pivot columns
  FrontPivots& result_;
  int k_ = 0;  // rows eliminated so far
};

}  // namespace

void factorFront(Eigen::Ref<Eigen::MatrixXd> panel, Eigen::Ref<Eigen::MatrixXd> below, bool root,
                 const PivotTest& test, FrontPivots& result, Eigen::MatrixXd& workspace) {
  Front(panel, below, test, result, workspace).eliminate(root);
}

}  // namespace gaitopt::ocp::kkt
