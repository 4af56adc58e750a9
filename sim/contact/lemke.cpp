#include "sim/contact/lemke.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace gaitopt::sim {
namespace {

/// Lemke works on w - M z - d z0 = q with d = 1. Variable indices: w_i is i, z_i is n + i and the
/// artificial z0 is 2n. The tableau keeps B^-1 explicitly because its rows, after the basic
/// value, make up the lexicographic ratio vectors.
struct Tableau {
  Eigen::MatrixXd binv;    ///< inverse of the basis matrix, n x n
  Eigen::VectorXd x;       ///< values of the basic variables, B^-1 q
  std::vector<int> basis;  ///< the variable basic in each row
  int n() const { return static_cast<int>(x.size()); }
};

void validate(const Eigen::MatrixXd& m, const Eigen::VectorXd& q, const LemkeOptions& options) {
  if (m.rows() != q.size() || m.cols() != q.size()) {
    throw std::invalid_argument("solveLcp: M is " + std::to_string(m.rows()) + " x " +
                                std::to_string(m.cols()) + " but q has " +
                                std::to_string(q.size()) + " rows; expected M n x n, q n");
  }
  if (!m.allFinite() || !q.allFinite()) {
    throw std::invalid_argument("solveLcp: M or q has a non-finite entry");
  }
  if (options.max_pivots < 1 || !(options.pivot_tolerance > 0) || !(options.ratio_tolerance > 0)) {
    throw std::invalid_argument(
        "solveLcp: LemkeOptions max_pivots, pivot_tolerance, ratio_tolerance must be positive");
  }
}

/// B^-1 a for the column a of variable `var` in [I, -M, -d].
Eigen::VectorXd column(const Tableau& t, const Eigen::MatrixXd& m, int var) {
  const int n = t.n();
  if (var < n) return t.binv.col(var);
  if (var < 2 * n) return -t.binv * m.col(var - n);
  return -t.binv.rowwise().sum();
}

bool tied(double a, double b, double tol) {
  return std::abs(a - b) <= tol * std::max({1.0, std::abs(a), std::abs(b)});
}

/// Whether row i's ratio vector (x_i, B^-1_i) / s_i is lexicographically below row j's. Rows of
/// B^-1 are independent, so exact ties cannot survive past the first component: this is what
/// keeps the basis sequence from cycling on degenerate q (Cottle, Pang & Stone, sec. 4.4).
bool lexLess(const Tableau& t, const Eigen::VectorXd& s, int i, int j, double tol) {
  for (int k = -1; k < t.n(); ++k) {
    const double a = (k < 0 ? t.x(i) : t.binv(i, k)) / s(i);
    const double b = (k < 0 ? t.x(j) : t.binv(j, k)) / s(j);
    if (!tied(a, b, tol)) return a < b;
  }
  return false;
}

/// First pivot: z0 enters at the value -min q that makes every w_i = q_i + z0 >= 0; the row of
/// the lexicographic minimum of (q_i, B^-1_i) / d_i leaves, so every row stays lexico-positive.
int initialRow(const Tableau& t, const Eigen::VectorXd& col, double tol) {
  const Eigen::VectorXd d = -col;
  int best = 0;
  for (int i = 1; i < t.n(); ++i) {
    if (lexLess(t, d, i, best, tol)) best = i;
  }
  return best;
}

/// Minimum-ratio test for the entering column: among rows with col_i > 0 (those whose basic
/// variable decreases), the lexicographic minimum ratio leaves. If z0 ties for the minimum it
/// leaves instead, which ends the run at a solution. nullopt: no row limits the column (a ray).
std::optional<int> leavingRow(const Tableau& t, const Eigen::VectorXd& col,
                              const LemkeOptions& options) {
  const double floor = options.pivot_tolerance * std::max(1.0, col.cwiseAbs().maxCoeff());
  std::optional<int> best;
  for (int i = 0; i < t.n(); ++i) {
    if (col(i) > floor && (!best || lexLess(t, col, i, *best, options.ratio_tolerance))) best = i;
  }
  if (!best) return best;
  const double min_ratio = t.x(*best) / col(*best);
  for (int i = 0; i < t.n(); ++i) {
    if (t.basis[i] == 2 * t.n() && col(i) > floor &&
        tied(t.x(i) / col(i), min_ratio, options.ratio_tolerance)) {
      return i;
    }
  }
  return best;
}

/// Gauss-Jordan pivot on (row, col): `entering` replaces the variable basic in `row`.
void pivot(Tableau& t, const Eigen::VectorXd& col, int row, int entering) {
  t.binv.row(row) /= col(row);
  t.x(row) /= col(row);
  for (int i = 0; i < t.n(); ++i) {
    if (i == row) continue;
    t.binv.row(i) -= col(i) * t.binv.row(row);
    t.x(i) -= col(i) * t.x(row);
  }
  t.basis[row] = entering;
}

/// z from the basic z_i (round-off below zero is clipped), w recomputed as M z + q.
LemkeResult extract(const Tableau& t, const Eigen::MatrixXd& m, const Eigen::VectorXd& q,
                    LemkeStatus status, int pivots) {
  const int n = t.n();
  Eigen::VectorXd z = Eigen::VectorXd::Zero(n);
  for (int row = 0; row < n; ++row) {
    const int var = t.basis[row];
    if (var >= n && var < 2 * n) z(var - n) = std::max(0.0, t.x(row));
  }
  return {status, z, m * z + q, pivots};
}

}  // namespace

const char* toString(LemkeStatus status) {
  switch (status) {
    case LemkeStatus::kSolved:
      return "solved";
    case LemkeStatus::kRayTermination:
      return "ray_termination";
    case LemkeStatus::kPivotLimit:
      return "pivot_limit";
  }
  return "unknown";
}

LemkeResult solveLcp(const Eigen::MatrixXd& m, const Eigen::VectorXd& q,
                     const LemkeOptions& options) {
  validate(m, q, options);
  const int n = static_cast<int>(q.size());
  if (n == 0 || q.minCoeff() >= 0) {
    return {LemkeStatus::kSolved, Eigen::VectorXd::Zero(n), q, 0};
  }
  Tableau t{Eigen::MatrixXd::Identity(n, n), q, std::vector<int>(n)};
  for (int i = 0; i < n; ++i) t.basis[i] = i;
  const int z0 = 2 * n;
  int entering = z0;
  Eigen::VectorXd col = column(t, m, entering);
  int row = initialRow(t, col, options.ratio_tolerance);
  for (int pivots = 1;; ++pivots) {
    const int leaving = t.basis[row];
    pivot(t, col, row, entering);
    if (leaving == z0) return extract(t, m, q, LemkeStatus::kSolved, pivots);
    if (pivots == options.max_pivots) return extract(t, m, q, LemkeStatus::kPivotLimit, pivots);
    entering = leaving < n ? leaving + n : leaving - n;  // the complement of what left
    col = column(t, m, entering);
    const std::optional<int> next = leavingRow(t, col, options);
    if (!next) return extract(t, m, q, LemkeStatus::kRayTermination, pivots);
    row = *next;
  }
}

}  // namespace gaitopt::sim
