#pragma once
/// The contract every constraint set and cost term of an Nlp keeps (nlp.hpp; Crocoddyl's
/// unittest/test_actions.cpp runs the same kind of suite over every action model), checked on
/// one set alone at a given point:
///   - every output entry is written (values into a NaN-seeded buffer) and finite;
///   - bounds have one entry per row, lower <= upper;
///   - Jacobian entries lie inside the set's rows and the decision vector; Hessian entries in
///     the lower triangle;
///   - the Jacobian equals central differences of the set's own values, the Hessian of the
///     Lagrangian lambda^T g (or factor * cost) central differences of its own Jacobian
///     (gradient), entry by entry, so an entry missing from the pattern fails too (the columns
///     the pattern does not name are differenced only when moving them changes the set:
///     columnsToDifference);
///   - the sequence of (row, col) positions is the one recorded at the first point.
/// Each check returns the list of broken clauses (empty: kept), each naming what broke where.
#include <cmath>
#include <functional>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <Eigen/Dense>
#include <Eigen/SparseCore>

#include "ocp/transcription/nlp.hpp"

namespace gaitopt::test {

using Positions = std::vector<std::pair<int, int>>;

inline Positions positionsOf(const ocp::Triplets& t) {
  Positions p;
  for (const auto& e : t) p.emplace_back(e.row(), e.col());
  return p;
}

using Sparse = Eigen::SparseMatrix<double>;

/// Sparse matrix of triplets (duplicates summed); records broken clauses for out-of-range,
/// non-finite or (lower_triangle) upper-triangle entries. Sparse, not dense: a dense n x n
/// Hessian per set and point made the contract's time the allocation and zeroing of memory.
inline Sparse sparseChecked(const ocp::Triplets& t, int rows, int cols, bool lower_triangle,
                            const std::string& what, std::vector<std::string>& broken) {
  ocp::Triplets inside;
  for (const auto& e : t) {
    if (e.row() < 0 || e.row() >= rows || e.col() < 0 || e.col() >= cols) {
      broken.push_back(
          fmt::format("{} entry ({}, {}) outside {} x {}", what, e.row(), e.col(), rows, cols));
      continue;
    }
    if (lower_triangle && e.row() < e.col())
      broken.push_back(fmt::format("{} entry ({}, {}) above the diagonal", what, e.row(), e.col()));
    if (!std::isfinite(e.value()))
      broken.push_back(fmt::format("{} entry ({}, {}) is {}", what, e.row(), e.col(), e.value()));
    inside.push_back(e);
  }
  Sparse m(rows, cols);
  m.setFromTriplets(inside.begin(), inside.end());
  return m;
}

/// Appends the non-zero entries of dense column `column` of a matrix, as column `col`.
inline void appendColumn(const Eigen::VectorXd& column, int col, ocp::Triplets& out) {
  for (Eigen::Index r = 0; r < column.size(); ++r)
    if (column(r) != 0) out.emplace_back(static_cast<int>(r), col, column(r));
}

/// Entry-wise comparison of an exact matrix with its central-difference estimate: |a - fd| <=
/// tol (max(1, max |fd|) + |fd_ij| / 10), the first few mismatches reported. Entries absent from
/// both are zero in both and pass; every entry present in either is compared.
inline void compareEntries(const Sparse& exact, const Sparse& fd, double tol,
                           const std::string& what, std::vector<std::string>& broken) {
  double scale = 1.0;
  for (int c = 0; c < fd.outerSize(); ++c)
    for (Sparse::InnerIterator it(fd, c); it; ++it) scale = std::max(scale, std::abs(it.value()));
  const Sparse difference = exact - fd;
  int reported = 0;
  for (int c = 0; c < difference.outerSize(); ++c)
    for (Sparse::InnerIterator it(difference, c); it; ++it) {
      const double f = fd.coeff(it.row(), it.col());
      if (!(std::abs(it.value()) <= tol * (scale + std::abs(f) / 10)) && reported++ < 5)
        broken.push_back(fmt::format("{} ({}, {}): exact {:.10g}, central differences {:.10g}",
                                     what, it.row(), it.col(), exact.coeff(it.row(), it.col()), f));
    }
}

/// The Jacobian and Hessian positions a set emitted at its first point.
struct RecordedPattern {
  Positions jacobian, hessian;
  bool recorded = false;
};

inline constexpr double kStep = 1e-6;    // central-difference step
inline constexpr double kJacTol = 1e-6;  // relative to the largest entry
inline constexpr double kHessTol = 1e-5;

inline double stepOf(const Eigen::VectorXd& x, int k) {
  return kStep * std::max(1.0, std::abs(x(k)));
}

/// The columns central differences must visit: those marked in `named` (what the set's own
/// derivative pattern touches) and, when moving every other column at once (random signs and
/// sizes of one difference step) changes any of `outputs` (values, derivatives) bit for bit, all
/// of them. A set reads a variable its pattern omits only in the second case, and the column-by-
/// column differences then name the entry; where it does not, the unvisited columns' differences
/// are exactly zero, as their full sweep would have found, at a fraction of its evaluations
/// (a set of one phase or one variant touches a part of the decision vector).
inline std::vector<int> columnsToDifference(
    const Eigen::VectorXd& x, const std::vector<char>& named,
    const std::function<std::vector<Eigen::VectorXd>(const Eigen::VectorXd&)>& outputs) {
  const int n = static_cast<int>(x.size());
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> u(0.5, 1.0);
  Eigen::VectorXd d = Eigen::VectorXd::Zero(n);
  std::vector<int> visited, all;
  for (int k = 0; k < n; ++k) {
    all.push_back(k);
    if (named[k])
      visited.push_back(k);
    else
      d(k) = (rng() % 2 ? 1 : -1) * u(rng) * stepOf(x, k);
  }
  if (visited.size() == all.size()) return all;
  const auto at = outputs(x), plus = outputs(x + d), minus = outputs(x - d);
  for (size_t i = 0; i < at.size(); ++i)
    if (plus[i] != at[i] || minus[i] != at[i]) return all;
  return visited;
}

/// The contract of constraint set `set` at `x` (size n) with multipliers `lambda` (its rows).
inline std::vector<std::string> checkConstraintSet(const ocp::ConstraintSet& set,
                                                   const Eigen::VectorXd& x,
                                                   const Eigen::VectorXd& lambda,
                                                   RecordedPattern& pattern) {
  std::vector<std::string> broken;
  const int m = set.rows(), n = static_cast<int>(x.size());
  const auto nan = std::numeric_limits<double>::quiet_NaN();
  auto values = [&](const Eigen::VectorXd& z) {
    Eigen::VectorXd g = Eigen::VectorXd::Constant(m, nan);
    set.values(z, g);
    return g;
  };
  const Eigen::VectorXd g = values(x);
  for (int r = 0; r < m; ++r)
    if (!std::isfinite(g(r)))
      broken.push_back(fmt::format("value row {} not written: {}", r, g(r)));
  const Eigen::VectorXd lo = set.lowerBounds(), hi = set.upperBounds();
  if (lo.size() != m || hi.size() != m)
    broken.push_back(
        fmt::format("bounds have {} and {} entries for {} rows", lo.size(), hi.size(), m));
  else if (!(lo.array() <= hi.array()).all())
    broken.push_back("a lower bound above its upper bound");

  ocp::Triplets jt, ht;
  set.jacobian(x, jt);
  set.hessian(x, lambda, ht);
  if (!pattern.recorded) pattern = {positionsOf(jt), positionsOf(ht), true};
  if (positionsOf(jt) != pattern.jacobian) broken.push_back("Jacobian sparsity changed");
  if (positionsOf(ht) != pattern.hessian) broken.push_back("Hessian sparsity changed");
  const Sparse jac = sparseChecked(jt, m, n, false, "Jacobian", broken);
  const Sparse hess =
      sparseChecked(ht, n, n, true, "Hessian", broken).selfadjointView<Eigen::Lower>();

  // J(z)^T lambda from the triplets, O(nonzeros): a dense m x n Jacobian per difference made the
  // contract quadratic in the problem's size (entries outside the matrix are reported above).
  auto lagrangianGradient = [&](const Eigen::VectorXd& z) -> Eigen::VectorXd {
    ocp::Triplets t;
    set.jacobian(z, t);
    Eigen::VectorXd g = Eigen::VectorXd::Zero(n);
    for (const auto& e : t)
      if (e.row() >= 0 && e.row() < m && e.col() >= 0 && e.col() < n)
        g(e.col()) += e.value() * lambda(e.row());
    return g;
  };
  std::vector<char> named(n, 0);
  for (const auto& e : jt)
    if (e.col() >= 0 && e.col() < n) named[e.col()] = 1;
  const auto columns = columnsToDifference(x, named, [&](const Eigen::VectorXd& z) {
    return std::vector<Eigen::VectorXd>{values(z), lagrangianGradient(z)};
  });
  ocp::Triplets fd_jac, fd_hess;
  for (const int k : columns) {
    const double h = stepOf(x, k);
    Eigen::VectorXd xp = x, xm = x;
    xp(k) += h;
    xm(k) -= h;
    appendColumn((values(xp) - values(xm)) / (2 * h), k, fd_jac);
    appendColumn((lagrangianGradient(xp) - lagrangianGradient(xm)) / (2 * h), k, fd_hess);
  }
  compareEntries(jac, sparseChecked(fd_jac, m, n, false, "", broken), kJacTol, "Jacobian", broken);
  compareEntries(hess, sparseChecked(fd_hess, n, n, false, "", broken), kHessTol, "Hessian",
                 broken);
  return broken;
}

/// The contract of cost term `cost` at `x`, the Hessian scaled by `factor`.
inline std::vector<std::string> checkCostTerm(const ocp::CostTerm& cost, const Eigen::VectorXd& x,
                                              double factor, RecordedPattern& pattern) {
  std::vector<std::string> broken;
  const int n = static_cast<int>(x.size());
  if (!std::isfinite(cost.value(x))) broken.push_back(fmt::format("value {}", cost.value(x)));
  auto gradient = [&](const Eigen::VectorXd& z) {
    Eigen::VectorXd grad = Eigen::VectorXd::Zero(n);  // gradient() adds into its buffer
    cost.gradient(z, grad);
    return grad;
  };
  const Eigen::VectorXd grad = gradient(x);
  if (!grad.allFinite()) broken.push_back("a gradient entry is not finite");
  ocp::Triplets ht;
  cost.hessian(x, factor, ht);
  if (!pattern.recorded) pattern = {{}, positionsOf(ht), true};
  if (positionsOf(ht) != pattern.hessian) broken.push_back("Hessian sparsity changed");
  const Sparse hess =
      sparseChecked(ht, n, n, true, "Hessian", broken).selfadjointView<Eigen::Lower>();
  std::vector<char> named(n, 0);
  for (const auto& e : ht)
    if (e.row() >= 0 && e.row() < n && e.col() >= 0 && e.col() < n)
      named[e.row()] = named[e.col()] = 1;
  for (int k = 0; k < n; ++k)
    if (grad(k) != 0) named[k] = 1;
  const auto columns = columnsToDifference(x, named, [&](const Eigen::VectorXd& z) {
    return std::vector<Eigen::VectorXd>{Eigen::VectorXd::Constant(1, cost.value(z)), gradient(z)};
  });
  ocp::Triplets fd_grad, fd_hess;
  for (const int k : columns) {
    const double h = stepOf(x, k);
    Eigen::VectorXd xp = x, xm = x;
    xp(k) += h;
    xm(k) -= h;
    appendColumn(Eigen::VectorXd::Constant(1, (cost.value(xp) - cost.value(xm)) / (2 * h)), k,
                 fd_grad);
    appendColumn(factor * (gradient(xp) - gradient(xm)) / (2 * h), k, fd_hess);
  }
  compareEntries(grad.transpose().sparseView(), sparseChecked(fd_grad, 1, n, false, "", broken),
                 kJacTol, "gradient", broken);
  compareEntries(hess, sparseChecked(fd_hess, n, n, false, "", broken), kHessTol, "Hessian",
                 broken);
  return broken;
}

}  // namespace gaitopt::test
