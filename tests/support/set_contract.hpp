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
///     (gradient), entry by entry, so an entry missing from the pattern fails too;
///   - the sequence of (row, col) positions is the one recorded at the first point.
/// Each check returns the list of broken clauses (empty: kept), each naming what broke where.
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <Eigen/Dense>

#include "ocp/transcription/nlp.hpp"

namespace gaitopt::test {

using Positions = std::vector<std::pair<int, int>>;

inline Positions positionsOf(const ocp::Triplets& t) {
  Positions p;
  for (const auto& e : t) p.emplace_back(e.row(), e.col());
  return p;
}

/// Dense matrix of triplets (duplicates summed); records broken clauses for out-of-range,
/// non-finite or (lower_triangle) upper-triangle entries.
inline Eigen::MatrixXd denseChecked(const ocp::Triplets& t, int rows, int cols, bool lower_triangle,
                                    const std::string& what, std::vector<std::string>& broken) {
  Eigen::MatrixXd m = Eigen::MatrixXd::Zero(rows, cols);
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
    m(e.row(), e.col()) += e.value();
  }
  return m;
}

/// Entry-wise comparison of an exact matrix with its central-difference estimate: |a - fd| <=
/// tol (max(1, max |fd|) + |fd_ij| / 10), the first few mismatches reported.
inline void compareEntries(const Eigen::MatrixXd& exact, const Eigen::MatrixXd& fd, double tol,
                           const std::string& what, std::vector<std::string>& broken) {
  const double scale = std::max(1.0, fd.cwiseAbs().maxCoeff());
  int reported = 0;
  for (Eigen::Index r = 0; r < exact.rows(); ++r)
    for (Eigen::Index c = 0; c < exact.cols(); ++c) {
      const double d = std::abs(exact(r, c) - fd(r, c));
      if (!(d <= tol * (scale + std::abs(fd(r, c)) / 10)) && reported++ < 5)
        broken.push_back(fmt::format("{} ({}, {}): exact {:.10g}, central differences {:.10g}",
                                     what, r, c, exact(r, c), fd(r, c)));
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
  const Eigen::MatrixXd jac = denseChecked(jt, m, n, false, "Jacobian", broken);
  const Eigen::MatrixXd hess_lower = denseChecked(ht, n, n, true, "Hessian", broken);
  const Eigen::MatrixXd hess = hess_lower.selfadjointView<Eigen::Lower>();

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
  Eigen::MatrixXd fd_jac(m, n), fd_hess(n, n);
  for (int k = 0; k < n; ++k) {
    const double h = kStep * std::max(1.0, std::abs(x(k)));
    Eigen::VectorXd xp = x, xm = x;
    xp(k) += h;
    xm(k) -= h;
    fd_jac.col(k) = (values(xp) - values(xm)) / (2 * h);
    fd_hess.col(k) = (lagrangianGradient(xp) - lagrangianGradient(xm)) / (2 * h);
  }
  compareEntries(jac, fd_jac, kJacTol, "Jacobian", broken);
  compareEntries(hess, fd_hess, kHessTol, "Hessian", broken);
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
  const Eigen::MatrixXd hess =
      denseChecked(ht, n, n, true, "Hessian", broken).selfadjointView<Eigen::Lower>();
  Eigen::MatrixXd fd_grad(1, n), fd_hess(n, n);
  for (int k = 0; k < n; ++k) {
    const double h = kStep * std::max(1.0, std::abs(x(k)));
    Eigen::VectorXd xp = x, xm = x;
    xp(k) += h;
    xm(k) -= h;
    fd_grad(0, k) = (cost.value(xp) - cost.value(xm)) / (2 * h);
    fd_hess.col(k) = factor * (gradient(xp) - gradient(xm)) / (2 * h);
  }
  compareEntries(grad.transpose(), fd_grad, kJacTol, "gradient", broken);
  compareEntries(hess, fd_hess, kHessTol, "Hessian", broken);
  return broken;
}

}  // namespace gaitopt::test
