#include "ocp/solve/kkt/kkt_solver.hpp"

#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <utility>

#include "ocp/solve/kkt/kkt_pairs.hpp"
#include "ocp/solve/kkt/pair_order.hpp"
#include "ocp/solve/kkt/kkt_statistics.hpp"

namespace gaitopt::ocp::kkt {

namespace {

// A pivot this much smaller than the largest entry of the equilibrated matrix
// (multifrontal_ldl.cpp) is taken for zero: it is moved to +-tiny (and counted) and MUMPS
// decides. Unscaled, the diagonal of Ipopt's matrix spans twenty decades near the optimum
// (Sigma = z / s from 1e-11 to 1e15), which is why the bound was set this low; equilibrated,
// 1e-20 and 1e-30 gave the same solves on the five-link default, strike and work configs.
constexpr double kTinyPivot = 1e-30;

// Ipopt's residual_ratio_max (IpPDFullSpaceSolver.cpp): a solution whose residual ratio is above
// it is refined. One that KktSolver's own refinement leaves above it is factorized again with a
// larger pivot threshold, and by MUMPS if the largest one does not reach it either.
constexpr double kResidualRatioMax = 1e-10;
// Refinement steps before raising the threshold: two, as with the static pivots before, where
// without them half the five-link default's solves went to MUMPS.
constexpr int kOwnRefinementSteps = 2;
// The pivot threshold u (front_ldl.hpp): Ipopt's default pivot tolerance for MUMPS
// (mumps_pivtol) to start with, raised a hundredfold per inexact solve up to MUMPS's own default
// (CNTL(1) = 0.01), and kept for the later matrices, as Ipopt keeps a raised mumps_pivtol. On
// the five-link default, u = 0.01 from the start delays 4 500 rows per factorization and takes
// 2.5 times as long; u = 1e-6 delays 9.
constexpr double kFirstThreshold = 1e-6;
constexpr double kLargestThreshold = 0.01;
constexpr double kThresholdStep = 100;

/// Ipopt's measure of a solution's accuracy (PDFullSpaceSolver::ComputeResidualRatio).
double residualRatio(const Eigen::VectorXd& residual, const Eigen::VectorXd& x,
                     const Eigen::VectorXd& b) {
  const double rhs = b.lpNorm<Eigen::Infinity>();
  return residual.lpNorm<Eigen::Infinity>() /
         (std::min(x.lpNorm<Eigen::Infinity>(), 1e6 * rhs) + rhs);
}


}  // namespace

KktSolver::KktSolver(SymmetricPattern pattern)
    : pattern_(std::move(pattern)),
      constraintStart_(constraintRowsStart(pattern_)),
      threshold_(kFirstThreshold) {}

void KktSolver::analyse(const double* values) {
  mustPair_.resize(pattern_.n, 0);
  for (int row : zeroDiagonalVariables(pattern_, values, constraintStart_)) mustPair_[row] = 1;
  std::vector<int> rows;
  for (int row = 0; row < pattern_.n; ++row)
    if (mustPair_[row]) rows.push_back(row);
  const std::vector<PivotPair> pairs = kktPivotPairs(pattern_, values, constraintStart_, rows);
  paired_.assign(pattern_.n, 0);
  for (const PivotPair& p : pairs) paired_[p.first] = paired_[p.second] = 1;
  ldl_ = std::make_unique<MultifrontalLdl>(pattern_, pairedMinimumDegreeOrder(pattern_, pairs));
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
  factorizeOwn(values);
}

// A pivot below tiny, which only a (nearly) singular matrix leaves: MUMPS decides whether A is
// singular (Ipopt then regularises the constraints) and factorizes it if not.
void KktSolver::factorizeOwn(const double* values) {
  ldl_->factorize(values, {threshold_, kTinyPivot});
  factor_ = Factor::kOwn;
  KktStatistics& counts = threadKktStatistics();
  counts.delayed_pivots += ldl_->delayedPivots();
  if (ldl_->perturbedPivots() == 0) return;
  ++counts.zero_pivot_fallbacks;
  factorizeWithMumps(values);
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
  const int allowed = std::max(refinementSteps, kOwnRefinementSteps);
  int steps = 0;
  try {
    double ratio = solveAndRefine(values, rhs, allowed, steps);
    while (ratio > kResidualRatioMax && factor_ == Factor::kOwn) {
      ++threadKktStatistics().inexact_refactorizations;
      if (threshold_ < kLargestThreshold) {
        threshold_ = std::min(kLargestThreshold, threshold_ * kThresholdStep);
        factorizeOwn(values);
      } else {
        ++threadKktStatistics().inexact_fallbacks;
        factorizeWithMumps(values);
      }
      std::copy(b.begin(), b.end(), rhs);
      ratio = solveAndRefine(values, rhs, allowed, steps);
    }
  } catch (const SingularMatrix&) {
    // Too late to tell Ipopt (it takes a solve's failure for an internal error): keep the own
    // factors' solution, whose residual Ipopt's own refinement then measures.
    factor_ = Factor::kOwnMumpsRefused;
    std::copy(b.begin(), b.end(), rhs);
    solveAndRefine(values, rhs, allowed, steps);
  }
  return steps;
}

}  // namespace gaitopt::ocp::kkt
