#include "ocp/solve/kkt/kkt_solver.hpp"

#include <Eigen/SparseCore>
#include <algorithm>
#include <cmath>
#include <utility>

#include "ocp/solve/kkt/kkt_observer.hpp"
#include "ocp/solve/kkt/kkt_pairs.hpp"
#include "ocp/solve/kkt/kkt_statistics.hpp"
#include "ocp/solve/kkt/pair_order.hpp"

namespace gaitopt::ocp::kkt {

namespace {

// A pivot this much smaller than the largest entry (of A for the static pivots, of the
// equilibrated S A S for the pivoting ones, multifrontal_ldl.cpp) is taken for zero: it is moved
// to +-tiny (and counted), and the matrix goes to the pivoting factorization or to MUMPS. Far
// below 1e-16 because the diagonal of Ipopt's matrix spans twenty decades near the optimum
// (Sigma = z / s from 1e-11 to 1e15 on the five-link problem): at 1e-20 the static pivots clamped
// the slack rows' true pivots and the five-link solve did not converge in 500 iterations.
constexpr double kTinyPivot = 1e-30;

// Ipopt's residual_ratio_max (IpPDFullSpaceSolver.cpp): a solution whose residual ratio is above
// it is refined. One that KktSolver's own refinement leaves above it is factorized again: with
// pivoting if it came from the static pivots (which can lose every digit once the barrier
// parameter is small: the compass-gait walk's ratio reached 0.4 at mu = 3e-8), else with a
// larger pivot threshold, and by MUMPS if the largest one does not reach it either.
constexpr double kResidualRatioMax = 1e-10;
// Refinement steps before turning from the static pivots to pivoting, or raising the threshold:
// two; without them half the five-link default's solves left the static pivots. Past those, the
// static pivots' solution is refined on while every step gains at least kRefinementGain, up to
// kMostRefinementSteps: at the five-link default's last matrix (mu = 3e-8) each step gains two
// decades, from 7e-5 to 3e-12 in five steps (about 0.1 ms each), where the pivoting
// factorization it turned to took 5 ms, a tenth of the whole solve. A step that gains less says
// the factors have lost too many digits for refinement to recover them. The pivoting factors
// keep two steps: an inexact solve there says their threshold is too small, which a larger one
// mends.
constexpr int kRefinementSteps = 2;
constexpr int kMostRefinementSteps = 8;
constexpr double kRefinementGain = 10;
// The pivoting factorization's threshold u (front_ldl.hpp): Ipopt's default pivot tolerance
// for MUMPS (mumps_pivtol) to start with, raised a hundredfold per inexact solve up to MUMPS's own
// default (CNTL(1) = 0.01), and kept for the later matrices, as Ipopt keeps a raised mumps_pivtol.
// On the five-link default, u = 0.01 from the start delays 4 500 rows per factorization and takes
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

double largestMagnitude(const double* values, int count) {
  double largest = 0;
  for (int k = 0; k < count; ++k) largest = std::max(largest, std::abs(values[k]));
  return largest;
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
  order_ = pairedMinimumDegreeOrder(pattern_, pairs);
  static_ = std::make_unique<BlockLdl>(pattern_, order_);
  pivoting_.reset();
  ++analyses_;
  ++threadKktStatistics().analyses;
}

bool KktSolver::lostADiagonal(const double* values) const {
  for (int row : zeroDiagonalVariables(pattern_, values, constraintStart_))
    if (!paired_[row]) return true;
  return false;
}

// An audit (kkt_observer.hpp) sees each matrix with the count Ipopt will read for it.
void KktSolver::factorize(const double* values) {
  chooseAndFactorize(values);
  if (const FactorizationObserver& observe = threadFactorizationObserver())
    observe(pattern_, values, negativeEigenvalues());
}

// The static pivots first, while they hold: a zero pivot, or an inertia other than a KKT
// matrix's (one negative eigenvalue per constraint row), which from static pivots can be a
// small pivot's rounding, turns this solver to pivoting for the rest of its matrices. With
// Ipopt's finite-difference Jacobian on RABBIT the static count was off at every iteration
// (delta_w 1e4, 500 iterations, where MUMPS's pivoting needs no regularisation and converges in
// 35).
void KktSolver::chooseAndFactorize(const double* values) {
  ++threadKktStatistics().factorizations;
  if (!static_ || lostADiagonal(values)) analyse(values);
  if (!usePivoting_) {
    static_->factorize(values, kTinyPivot * largestMagnitude(values, pattern_.nonZeros()));
    factor_ = Factor::kStatic;
    if (static_->perturbedPivots() == 0 &&
        static_->negativeEigenvalues() == pattern_.n - constraintStart_)
      return;
    usePivoting_ = true;
  }
  factorizePivoting(values);
}

// A pivot below tiny, which only a (nearly) singular matrix leaves: MUMPS decides whether A is
// singular (Ipopt then regularises the constraints) and factorizes it if not.
void KktSolver::factorizePivoting(const double* values) {
  if (!pivoting_) pivoting_ = std::make_unique<MultifrontalLdl>(pattern_, order_);
  pivoting_->factorize(values, {threshold_, kTinyPivot});
  factor_ = Factor::kPivoting;
  KktStatistics& counts = threadKktStatistics();
  ++counts.pivoting_factorizations;
  counts.delayed_pivots += pivoting_->delayedPivots();
  if (pivoting_->perturbedPivots() == 0) return;
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
  switch (factor_) {
    case Factor::kStatic:
      return static_->negativeEigenvalues();
    case Factor::kMumps:
      return mumps_->negativeEigenvalues();
    default:
      return pivoting_->negativeEigenvalues();
  }
}

void KktSolver::applyInverse(double* x) const {
  switch (factor_) {
    case Factor::kStatic:
      return static_->solve(x);
    case Factor::kMumps:
      return mumps_->solve(x);
    default:
      return pivoting_->solve(x);
  }
}

// See kMostRefinementSteps.
bool KktSolver::worthRefining(int steps, int refinementSteps, double lastGain) const {
  if (steps < refinementSteps) return true;
  return factor_ == Factor::kStatic && steps < kMostRefinementSteps && lastGain >= kRefinementGain;
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
  double gain = kRefinementGain;
  for (steps = 0; ratio > kResidualRatioMax && worthRefining(steps, refinementSteps, gain);
       ++steps) {
    applyInverse(residual.data());
    x += residual;
    residual = b - lower.selfadjointView<Eigen::Lower>() * x;
    const double last = ratio;
    ratio = residualRatio(residual, x, b);
    gain = last / ratio;
  }
  b = x;
  return ratio;
}

int KktSolver::solve(const double* values, double* rhs, int refinementSteps) {
  ++threadKktStatistics().solves;
  const std::vector<double> b(rhs, rhs + pattern_.n);
  const int allowed = std::max(refinementSteps, kRefinementSteps);
  int steps = 0;
  try {
    double ratio = solveAndRefine(values, rhs, allowed, steps);
    while (ratio > kResidualRatioMax &&
           (factor_ == Factor::kStatic || factor_ == Factor::kPivoting)) {
      ++threadKktStatistics().inexact_refactorizations;
      if (factor_ == Factor::kStatic) {
        usePivoting_ = true;
        factorizePivoting(values);
      } else if (threshold_ < kLargestThreshold) {
        threshold_ = std::min(kLargestThreshold, threshold_ * kThresholdStep);
        factorizePivoting(values);
      } else {
        ++threadKktStatistics().inexact_fallbacks;
        factorizeWithMumps(values);
      }
      std::copy(b.begin(), b.end(), rhs);
      ratio = solveAndRefine(values, rhs, allowed, steps);
    }
  } catch (const SingularMatrix&) {
    // Too late to tell Ipopt (it takes a solve's failure for an internal error): keep the
    // pivoting factors' solution, whose residual Ipopt's own refinement then measures.
    factor_ = Factor::kPivotingMumpsRefused;
    std::copy(b.begin(), b.end(), rhs);
    solveAndRefine(values, rhs, allowed, steps);
  }
  return steps;
}

}  // namespace gaitopt::ocp::kkt
