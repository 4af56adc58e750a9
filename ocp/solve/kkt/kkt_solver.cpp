#include "ocp/solve/kkt/kkt_solver.hpp"

#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <utility>

#include "ocp/solve/kkt/kkt_pairs.hpp"
#include "ocp/solve/kkt/kkt_statistics.hpp"

namespace gaitopt::ocp::kkt {

namespace {

// A pivot this much smaller than the largest entry is taken for zero: it is moved to +-tiny (and
// counted) instead of divided by. Far below 1e-16 because the diagonal of Ipopt's matrix spans
// twenty decades near the optimum (Sigma = z / s from 1e-11 to 1e10 on the five-link problem):
// at 1e-20 the slack rows' true pivots are clamped, the solves lose their digits and the
// five-link solve does not converge in 500 iterations; at 1e-30 it takes MUMPS's 15
// (results/solve_profile.md).
constexpr double kTinyPivot = 1e-30;

// Ipopt's residual_ratio_max (IpPDFullSpaceSolver.cpp): a solution whose residual ratio is above
// it is refined. One that KktSolver's own refinement leaves above it is solved again by MUMPS:
// static pivots chosen at the analysis can lose every digit once the barrier parameter is small
// (the compass-gait walk's ratio reached 0.4 at mu = 3e-8, and Ipopt's refinement stalled at
// 0.16); MUMPS's threshold pivoting does not. Measured on the five-link configs at five meshes
// (scripts/solver_robustness.sh): with the fallback on zero pivots only, 17 of 25 solves
// converged; with this and the inertia check, 19, against MUMPS's own 20 and 19 under its two
// orders (results/solve_profile.md).
constexpr double kResidualRatioMax = 1e-10;
// Refinement steps before giving up on the static pivots: two are enough on every shipped config
// at its own mesh (no fallback on the five-link default or RABBIT); without them half the
// five-link default's solves went to MUMPS.
constexpr int kOwnRefinementSteps = 2;

/// Ipopt's measure of a solution's accuracy (PDFullSpaceSolver::ComputeResidualRatio).
double residualRatio(const Eigen::VectorXd& residual, const Eigen::VectorXd& x,
                     const Eigen::VectorXd& b) {
  const double rhs = b.lpNorm<Eigen::Infinity>();
  return residual.lpNorm<Eigen::Infinity>() /
         (std::min(x.lpNorm<Eigen::Infinity>(), 1e6 * rhs) + rhs);
}

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
  ++threadKktStatistics().analyses;
}

bool KktSolver::lostADiagonal(const double* values) const {
  for (int row : zeroDiagonalVariables(pattern_, values, constraintStart_))
    if (!paired_[row]) return true;
  return false;
}

void KktSolver::factorize(const double* values) {
  ++threadKktStatistics().factorizations;
  if (!ldl_ || lostADiagonal(values)) analyse(values);
  ldl_->factorize(values, kTinyPivot * largestMagnitude(values, pattern_.nonZeros()));
  factor_ = Factor::kStatic;
  // A zero static pivot, or an inertia other than a KKT matrix's (one negative eigenvalue per
  // constraint row): MUMPS's threshold pivoting decides. Ipopt takes a wrong inertia for a
  // nonconvex W and regularises it; from static pivots it can be a small pivot's rounding, and
  // with Ipopt's finite-difference Jacobian on RABBIT it was, at every iteration (delta_w 1e4,
  // 500 iterations, where MUMPS needs none and converges in 35).
  KktStatistics& counts = threadKktStatistics();
  if (ldl_->perturbedPivots() > 0)
    ++counts.zero_pivot_fallbacks;
  else if (ldl_->negativeEigenvalues() != pattern_.n - constraintStart_)
    ++counts.inertia_fallbacks;
  else
    return;
  factorizeWithMumps(values);  // a singular A goes to Ipopt
}

void KktSolver::factorizeWithMumps(const double* values) {
  if (!mumps_) mumps_ = std::make_unique<MumpsFactor>(pattern_);
  mumps_->factorize(values);
  factor_ = Factor::kMumps;
  ++fallbacks_;
  ++threadKktStatistics().mumps_fallbacks;
}

int KktSolver::negativeEigenvalues() const {
  return factor_ == Factor::kMumps ? mumps_->negativeEigenvalues() : ldl_->negativeEigenvalues();
}

void KktSolver::applyInverse(double* x) const {
  if (factor_ == Factor::kMumps)
    mumps_->solve(x);
  else
    ldl_->solve(x);
}

double KktSolver::solveAndRefine(const double* values, double* rhs, int refinementSteps,
                                 int& steps) const {
  using Vector = Eigen::VectorXd;
  const Eigen::Map<const Eigen::SparseMatrix<double, Eigen::ColMajor, int>> lower(
      pattern_.n, pattern_.n, pattern_.nonZeros(), pattern_.outer.data(), pattern_.inner.data(),
      values);
  Eigen::Map<Vector> b(rhs, pattern_.n);
  Vector x = b;
  applyInverse(x.data());
  Vector residual = b - lower.selfadjointView<Eigen::Lower>() * x;
  double ratio = residualRatio(residual, x, b);
  for (steps = 0; steps < refinementSteps && ratio > kResidualRatioMax; ++steps) {
    applyInverse(residual.data());
    x += residual;
    residual = b - lower.selfadjointView<Eigen::Lower>() * x;
    ratio = residualRatio(residual, x, b);
  }
  b = x;
  return ratio;
}

int KktSolver::solve(const double* values, double* rhs, int refinementSteps) {
  const std::vector<double> b(rhs, rhs + pattern_.n);
  int steps = 0;
  const double ratio =
      solveAndRefine(values, rhs, std::max(refinementSteps, kOwnRefinementSteps), steps);
  if (ratio <= kResidualRatioMax || factor_ != Factor::kStatic) return steps;
  ++threadKktStatistics().inexact_fallbacks;
  try {
    factorizeWithMumps(values);
  } catch (const SingularMatrix&) {
    // Too late to tell Ipopt (it takes a solve's failure for an internal error): keep this
    // solution, whose residual Ipopt's own refinement then measures.
    factor_ = Factor::kStaticMumpsRefused;
    return steps;
  }
  std::copy(b.begin(), b.end(), rhs);
  solveAndRefine(values, rhs, refinementSteps, steps);
  return steps;
}

}  // namespace gaitopt::ocp::kkt
