#include "ocp/kkt/kkt_solver.hpp"

#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <utility>

#include "ocp/kkt/kkt_pairs.hpp"

namespace gaitopt::ocp::kkt {

namespace {

// A pivot this much smaller than the largest entry is taken for zero: it is moved to +-tiny (and
// counted) instead of divided by. Far below 1e-16 because the diagonal of Ipopt's matrix spans
// twenty decades near the optimum (Sigma = z / s from 1e-11 to 1e10 on the five-link problem):
// at 1e-20 the slack rows' true pivots are clamped, the solves lose their digits and the
// five-link solve does not converge in 500 iterations; at 1e-30 it takes MUMPS's 15
// (results/solve_profile.md).
constexpr double kTinyPivot = 1e-30;

double largestMagnitude(const double* values, int count) {
  double largest = 0;
  for (int k = 0; k < count; ++k) largest = std::max(largest, std::abs(values[k]));
  return largest;
}

}  // namespace

KktSolver::KktSolver(SymmetricPattern pattern)
    : pattern_(std::move(pattern)), constraintStart_(constraintRowsStart(pattern_)) {}

void KktSolver::analyse(const double* values) {
  mustPair_.resize(pattern_.n, 0);
  for (int row : zeroDiagonalVariables(pattern_, values, constraintStart_)) mustPair_[row] = 1;
  std::vector<int> rows;
  for (int row = 0; row < pattern_.n; ++row)
    if (mustPair_[row]) rows.push_back(row);
  const std::vector<PivotPair> pairs = kktPivotPairs(pattern_, values, constraintStart_, rows);
  paired_.assign(pattern_.n, 0);
  for (const PivotPair& p : pairs) paired_[p.first] = paired_[p.second] = 1;
  ldl_ = std::make_unique<BlockLdl>(pattern_, pairs);
  ++analyses_;
}

bool KktSolver::lostADiagonal(const double* values) const {
  for (int row : zeroDiagonalVariables(pattern_, values, constraintStart_))
    if (!paired_[row]) return true;
  return false;
}

void KktSolver::factorize(const double* values) {
  if (!ldl_ || lostADiagonal(values)) analyse(values);
  ldl_->factorize(values, kTinyPivot * largestMagnitude(values, pattern_.nonZeros()));
}

int KktSolver::solve(const double* values, double* rhs, int refinementSteps) const {
  using Vector = Eigen::VectorXd;
  const Eigen::Map<const Eigen::SparseMatrix<double, Eigen::ColMajor, int>> lower(
      pattern_.n, pattern_.n, pattern_.nonZeros(), pattern_.outer.data(), pattern_.inner.data(),
      values);
  Eigen::Map<Vector> b(rhs, pattern_.n);
  Vector x = b;
  ldl_->solve(x.data());
  int steps = 0;
  for (; steps < refinementSteps; ++steps) {
    Vector residual = b - lower.selfadjointView<Eigen::Lower>() * x;
    if (residual.lpNorm<Eigen::Infinity>() <= 1e-15 * b.lpNorm<Eigen::Infinity>()) break;
    ldl_->solve(residual.data());
    x += residual;
  }
  b = x;
  return steps;
}

}  // namespace gaitopt::ocp::kkt
