// gaitopt's KKT solver (ocp/solve/kkt/): block LDL^T with 2x2 pivots on matched constraint rows,
// against dense linear algebra on matrices built like Ipopt's augmented system, the matching's
// guarantees, and Pardiso's calling protocol as Ipopt's loader uses it.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "ocp/solve/kkt/block_ldl.hpp"
#include "ocp/solve/kkt/kkt_observer.hpp"
#include "ocp/solve/kkt/kkt_pairs.hpp"
#include "ocp/solve/kkt/kkt_solver.hpp"
#include "ocp/solve/kkt/kkt_statistics.hpp"
#include "ocp/solve/kkt/pair_order.hpp"
#include "support/dense_symmetric.hpp"

extern "C" {
void pardisoinit(void* pt, const int* mtype, const int* solver, int* iparm, double* dparm,
                 int* error);
void pardiso(void** pt, const int* maxfct, const int* mnum, const int* mtype, const int* phase,
             const int* n, const double* a, const int* ia, const int* ja, const int* perm,
             const int* nrhs, int* iparm, const int* msglvl, double* b, double* x, int* error,
             double* dparm);
}

namespace gaitopt::ocp::kkt {
namespace {

using test::backwardError;
using test::Lower;
using test::lowerOf;
using test::negativeEigenvalues;

/// A dense symmetric matrix laid out like Ipopt's augmented system (IpStdAugSystemSolver):
/// rows [x | s | y_c | y_d], W sparse with some zero diagonals, Sigma_s over twenty decades,
/// J_c and J_d sparse, -I between s and y_d, and no constraint diagonal. As in a well-posed
/// problem, a variable without a diagonal appears in some constraint.
struct AugmentedSystem {
  int nx, ns, nc;
  Eigen::MatrixXd dense;
  int n() const { return nx + 2 * ns + nc; }
  int constraintRows() const { return nc + ns; }
};

/// W indefinite, or (`Convexity::kConvexW`) positive semidefinite: diagonally dominant where
/// it has a diagonal, and no coupling where it has none, each variable without one in a
/// constraint of its own. J then has full rank on those variables, and the matrix a KKT
/// matrix's inertia, one negative eigenvalue per constraint row, as Ipopt's has near a minimum.
enum class Convexity { kIndefiniteW, kConvexW };

AugmentedSystem randomAugmentedSystem(unsigned seed, Convexity w = Convexity::kIndefiniteW,
                                      int nx = 40, int ns = 12, int nc = 20) {
  std::mt19937 g(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  AugmentedSystem a{nx, ns, nc, Eigen::MatrixXd::Zero(nx + 2 * ns + nc, nx + 2 * ns + nc)};
  auto link = [&](int i, int j, double v) { a.dense(i, j) = a.dense(j, i) = v; };
  const bool convex = w == Convexity::kConvexW;
  for (int i = 0; i < nx; ++i) {
    if (u(g) <= -0.3) continue;  // a zero diagonal
    const double scale = std::pow(10.0, 2 * u(g));
    a.dense(i, i) = convex ? scale : u(g) * scale;
    for (int j = 0; j < i; ++j)
      if (u(g) > 0.9 && (!convex || a.dense(j, j) != 0.0)) link(i, j, u(g));
  }
  if (convex)
    for (int i = 0; i < nx; ++i)
      if (a.dense(i, i) != 0.0) a.dense(i, i) += a.dense.row(i).head(nx).cwiseAbs().sum();
  const int s0 = nx, c0 = nx + ns, d0 = nx + ns + nc;
  for (int k = 0; k < ns; ++k) a.dense(s0 + k, s0 + k) = std::pow(10.0, 10 * u(g));  // Sigma_s
  auto constrain = [&](int row) {
    for (int t = 0; t < 3; ++t) link(row, static_cast<int>((u(g) + 1) / 2 * nx) % nx, u(g) * 3);
  };
  for (int k = 0; k < nc; ++k) constrain(c0 + k);
  for (int k = 0; k < ns; ++k) {
    constrain(d0 + k);
    link(d0 + k, s0 + k, -1.0);
  }
  // Each variable without a diagonal in a constraint; for a convex W each in its own, so that
  // J has full rank on them and the matrix is not singular.
  int own = 0;
  for (int i = 0; i < nx; ++i) {
    if (a.dense(i, i) != 0.0) continue;
    const int row = convex ? own++ % nc : static_cast<int>((u(g) + 1) / 2 * nc) % nc;
    link(c0 + row, i, convex ? 1 + 0.5 * u(g) : 1 + u(g));
  }
  return a;
}

TEST(KktPairs, FindTheConstraintBlockAndPairEveryConstraintRowAcrossIt) {
  for (unsigned seed = 1; seed <= 400; ++seed) {
    const AugmentedSystem a = randomAugmentedSystem(seed);
    const Lower l = lowerOf(a.dense);
    const int split = constraintRowsStart(l.pattern);
    EXPECT_EQ(split, a.nx + a.ns) << "seed " << seed;
    const std::vector<int> zero = zeroDiagonalVariables(l.pattern, l.values.data(), split);
    for (int row : zero) EXPECT_EQ(a.dense(row, row), 0.0);
    const auto pairs = kktPivotPairs(l.pattern, l.values.data(), split, zero);
    std::set<int> used;
    for (const PivotPair& p : pairs) {
      EXPECT_LT(p.first, split);
      if (p.second < split) {  // two variable rows: one of them without a diagonal
        EXPECT_EQ(a.dense(p.first, p.first) * a.dense(p.second, p.second), 0.0);
      }
      EXPECT_NE(a.dense(p.first, p.second), 0.0) << "a pair must couple";
      EXPECT_TRUE(used.insert(p.first).second && used.insert(p.second).second) << "disjoint";
    }
    for (int row = split; row < a.n(); ++row) EXPECT_TRUE(used.count(row)) << "seed " << seed;
  }
}

TEST(KktPairs, AnAugmentingPathFreesTheStrongPartnerForTheRowThatHasNoOther) {
  // Constraint 3 couples strongly to variable 0 and weakly to 1; constraint 2 only to 0.
  // Greedy strongest-first would leave row 2 unpaired; Kuhn's augmenting path pairs (0, 2)
  // and (1, 3).
  Eigen::MatrixXd m = Eigen::MatrixXd::Zero(4, 4);
  m(0, 0) = m(1, 1) = 1.0;
  m(3, 0) = m(0, 3) = 5.0;
  m(3, 1) = m(1, 3) = 0.1;
  m(2, 0) = m(0, 2) = 1.0;
  const Lower l = lowerOf(m);
  const auto pairs = kktPivotPairs(l.pattern, l.values.data(), constraintRowsStart(l.pattern), {});
  ASSERT_EQ(pairs.size(), 2U);
  for (const PivotPair& p : pairs) EXPECT_EQ(p.second, p.first == 0 ? 2 : 3);
}

TEST(KktSolver, SolvesAndCountsTheInertiaOfAugmentedSystemsLikeDenseAlgebra) {
  // Static pivots cannot promise every matrix: a zero-diagonal variable row whose constraint and
  // W neighbours are all taken is eliminated alone and its pivot may be zero, a small pivot can
  // grow the factor and cost digits that refinement does not recover, and its rounding can flip
  // the inertia. Those matrices are factorized again with pivoting, and so is every matrix whose
  // inertia is not a KKT matrix's; a (nearly) singular one goes on to MUMPS, which reports the
  // few it finds singular (a constraint dependent on the rows without a diagonal). Every other
  // matrix, W convex or not, gets a dense eigen-decomposition's inertia and the backward error
  // of a stable method, but for the one or two in 400 so ill-conditioned that the two disagree
  // on the sign of an eigenvalue; MUMPS factorizes at most the singular ones.
  for (const Convexity w : {Convexity::kIndefiniteW, Convexity::kConvexW}) {
    int singular = 0, exact = 0, accurate = 0, fallbacks = 0;
    for (unsigned seed = 1; seed <= 400; ++seed) {
      const AugmentedSystem a = randomAugmentedSystem(seed, w);
      const Lower l = lowerOf(a.dense);
      KktSolver solver(l.pattern);
      try {
        solver.factorize(l.values.data());
      } catch (const SingularMatrix&) {
        ++singular;
        continue;
      }
      if (solver.negativeEigenvalues() == negativeEigenvalues(a.dense)) ++exact;
      const Eigen::VectorXd b = Eigen::VectorXd::Random(a.n());
      Eigen::VectorXd x = b;
      solver.solve(l.values.data(), x.data(), 0);
      if (backwardError(a.dense, x, b) < 1e-14) ++accurate;
      fallbacks += solver.fallbacks();
    }
    const std::string family = w == Convexity::kConvexW ? "convex_" : "indefinite_";
    RecordProperty(family + "singular", singular);
    RecordProperty(family + "fallbacks", fallbacks);
    EXPECT_LE(singular, 8);  // 2 %
    EXPECT_GE(exact, 400 - singular - 2);
    EXPECT_GE(accurate, 400 - singular - 2);
    EXPECT_LE(fallbacks, singular + 2);
  }
}

/// The static pivots of `a` alone: BlockLdl in KktSolver's order of its pairs.
BlockLdl staticPivots(const Lower& l) {
  const int split = constraintRowsStart(l.pattern);
  const std::vector<int> zero = zeroDiagonalVariables(l.pattern, l.values.data(), split);
  BlockLdl ldl(l.pattern, pairedMinimumDegreeOrder(
                              l.pattern, kktPivotPairs(l.pattern, l.values.data(), split, zero)));
  double largest = 0;
  for (double v : l.values) largest = std::max(largest, std::abs(v));
  ldl.factorize(l.values.data(), 1e-30 * largest);  // KktSolver's threshold
  return ldl;
}

TEST(KktSolver, AMatrixWhoseStaticPivotsFailIsFactorizedWithPivotingNotByMumps) {
  int tried = 0;
  for (unsigned seed = 1; seed <= 400; ++seed) {
    const AugmentedSystem a = randomAugmentedSystem(seed);
    const Lower l = lowerOf(a.dense);
    if (staticPivots(l).perturbedPivots() == 0) continue;  // a zero static pivot
    const Eigen::VectorXd ev =
        Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(a.dense).eigenvalues();
    if (ev.cwiseAbs().minCoeff() < 1e-10 * ev.cwiseAbs().maxCoeff()) continue;  // singular
    ++tried;
    KktSolver solver(l.pattern);
    const KktStatistics before = threadKktStatistics();
    solver.factorize(l.values.data());
    EXPECT_EQ(solver.fallbacks(), 0) << "seed " << seed;
    // What summary.json's kkt record reads (ocp/solve/ipopt_adapter.cpp): this thread's counts.
    EXPECT_EQ(threadKktStatistics().factorizations - before.factorizations, 1);
    EXPECT_EQ(threadKktStatistics().pivoting_factorizations - before.pivoting_factorizations, 1);
    EXPECT_EQ(solver.negativeEigenvalues(), negativeEigenvalues(a.dense)) << "seed " << seed;
    const Eigen::VectorXd b = Eigen::VectorXd::Random(a.n());
    Eigen::VectorXd x = b;
    solver.solve(l.values.data(), x.data(), 0);
    EXPECT_LT(backwardError(a.dense, x, b), 1e-14) << "seed " << seed;
  }
  EXPECT_GE(tried, 1) << "the family has a matrix whose static pivots fail";
}

// The audit's window (bench/inertia_audit.cpp): each factorization, static or pivoting, is seen
// once, with the matrix factorized and the count Ipopt is told, which is the dense count.
TEST(KktSolver, TheObserverSeesEveryFactorizationWithTheInertiaIpoptIsTold) {
  struct Seen {
    int n, negative;
    double first;
  };
  std::vector<Seen> seen;
  // A failed assertion must not leave the thread's observer writing into `seen` after it is gone.
  struct ResetObserver {
    ~ResetObserver() { threadFactorizationObserver() = nullptr; }
  } reset;
  threadFactorizationObserver() = [&seen](const SymmetricPattern& p, const double* v, int neg) {
    seen.push_back({p.n, neg, v[0]});
  };
  std::vector<int> dense;
  const int pivotingBefore = threadKktStatistics().pivoting_factorizations;
  for (unsigned seed = 1; seed <= 40; ++seed) {
    const AugmentedSystem a = randomAugmentedSystem(seed);
    const Eigen::VectorXd ev =
        Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(a.dense).eigenvalues();
    if (ev.cwiseAbs().minCoeff() < 1e-10 * ev.cwiseAbs().maxCoeff()) continue;  // singular
    const Lower l = lowerOf(a.dense);
    KktSolver solver(l.pattern);
    solver.factorize(l.values.data());
    ASSERT_EQ(seen.size(), dense.size() + 1) << "seed " << seed;
    EXPECT_EQ(seen.back().n, a.n());
    EXPECT_EQ(seen.back().first, l.values[0]);
    EXPECT_EQ(seen.back().negative, solver.negativeEigenvalues());
    dense.push_back(negativeEigenvalues(a.dense));
    EXPECT_EQ(seen.back().negative, dense.back()) << "seed " << seed;
  }
  EXPECT_GE(dense.size(), 5u);
  EXPECT_GT(threadKktStatistics().pivoting_factorizations, pivotingBefore)
      << "both kinds of factorization seen";
  threadFactorizationObserver() = nullptr;
  const Lower l = lowerOf(randomAugmentedSystem(1, Convexity::kConvexW).dense);
  KktSolver(l.pattern).factorize(l.values.data());
  EXPECT_EQ(seen.size(), dense.size()) << "seen after the observer was reset";
}

TEST(KktSolver, ASingularMatrixIsReportedAsSuch) {
  // Two equal constraint rows: J has rank 1, so the KKT matrix is singular, and Ipopt must hear
  // it (it then regularises the constraints) rather than get a clamped factor.
  Eigen::MatrixXd m = Eigen::MatrixXd::Zero(3, 3);
  m(0, 0) = 1.0;
  m(1, 0) = m(0, 1) = 1.0;
  m(2, 0) = m(0, 2) = 1.0;
  const Lower l = lowerOf(m);
  KktSolver solver(l.pattern);
  EXPECT_THROW(solver.factorize(l.values.data()), SingularMatrix);
}

TEST(KktSolver, AnalysesAgainWhenAVariableRowLosesItsDiagonal) {
  // Ipopt's first matrix (least-squares multipliers) has an identity where W will be.
  const AugmentedSystem a = randomAugmentedSystem(7, Convexity::kConvexW);
  Eigen::MatrixXd first = a.dense;
  for (int i = 0; i < a.nx; ++i) first(i, i) = 1.0;
  const Lower l0 = lowerOf(first), l1 = lowerOf(a.dense);
  ASSERT_EQ(l0.values.size(), l1.values.size());  // same pattern: the zeros are stored
  KktSolver solver(l0.pattern);
  solver.analyse(l0.values.data());
  solver.factorize(l0.values.data());
  EXPECT_EQ(solver.analyses(), 1);
  const int fallbacks = solver.fallbacks();  // the first matrix's W couplings may be indefinite
  solver.factorize(l1.values.data());
  EXPECT_EQ(solver.analyses(), 2);
  EXPECT_EQ(solver.negativeEigenvalues(), negativeEigenvalues(a.dense));
  EXPECT_EQ(solver.fallbacks(), fallbacks) << "the new pairs factorize it";
}

/// A solve of a matrix with the factors of another.
struct ScaledSolve {
  double ratio;   ///< the residual ratio reached against the matrix solved
  int steps;      ///< refinement steps of the last solution
  int pivoting;   ///< pivoting factorizations the solve added
  int fallbacks;  ///< the solver's factorizations by MUMPS
};

/// A solve of `a` scaled by `scale` with the factors of `a`, as factors that lost digits are:
/// each refinement step multiplies the error by 1 - scale (A^-1 (scale A) = scale I).
ScaledSolve solveWithScaledFactors(const AugmentedSystem& a, double scale) {
  const Lower l = lowerOf(a.dense);
  KktSolver solver(l.pattern);
  solver.factorize(l.values.data());
  std::vector<double> scaled = l.values;
  for (double& v : scaled) v *= scale;
  std::srand(5);  // Eigen's Random draws from std::rand
  const Eigen::VectorXd b = Eigen::VectorXd::Random(a.n());
  Eigen::VectorXd x = b;
  const int before = threadKktStatistics().pivoting_factorizations;
  const int steps = solver.solve(scaled.data(), x.data(), 0);  // Ipopt allows none
  return {(b - scale * a.dense * x).lpNorm<Eigen::Infinity>() /
              (x.lpNorm<Eigen::Infinity>() + b.lpNorm<Eigen::Infinity>()),
          steps, threadKktStatistics().pivoting_factorizations - before, solver.fallbacks()};
}

TEST(KktSolver, RefinesTheSolutionAgainstTheMatrixItIsGivenToIpoptsResidualRatio) {
  // The pivoting factorization leaves nothing to refine on these systems, so the solve is given
  // a matrix 1e-7 away from the factorized one: the factors are then an approximate inverse,
  // as a factorization that lost digits would be, and refinement must close the gap.
  const ScaledSolve s =
      solveWithScaledFactors(randomAugmentedSystem(3, Convexity::kConvexW), 1 + 1e-7);
  EXPECT_GE(s.steps, 1);
  EXPECT_EQ(s.fallbacks, 0) << "refinement suffices here";
  EXPECT_LT(s.ratio, 1e-10);  // Ipopt's residual_ratio_max
}

TEST(KktSolver, RefinesPastTwoStepsWhileEachGainsTenfoldAndFactorizesAgainWhenItStalls) {
  // Factors 1 % off gain two decades a step, as the five-link default's static factors do at
  // its last matrix (mu = 3e-8): more than the two steps a solve always may take reach Ipopt's
  // ratio, where a factorization with pivoting, which the solve turned to after two, took fifty
  // times as long.
  const AugmentedSystem a = randomAugmentedSystem(3, Convexity::kConvexW);
  const ScaledSolve close = solveWithScaledFactors(a, 1.01);
  EXPECT_LT(close.ratio, 1e-10);
  EXPECT_GE(close.steps, 3);
  EXPECT_LE(close.steps, 6);
  EXPECT_EQ(close.pivoting, 0) << "refinement suffices";
  // Factors 40 % off gain 2.5 times a step: refinement stops after the two steps it always
  // takes, and the matrix is factorized again, with pivoting, which solves it exactly.
  const ScaledSolve far = solveWithScaledFactors(a, 1.4);
  EXPECT_LT(far.ratio, 1e-10);
  EXPECT_LE(far.steps, 2);
  EXPECT_EQ(far.pivoting, 1);
}

/// Pardiso's arrays: the upper triangle by rows, 1-based (the lower triangle by columns).
struct PardisoArrays {
  std::vector<int> ia, ja;
  std::vector<double> a;
};

PardisoArrays pardisoArrays(const Eigen::MatrixXd& m) {
  const Lower l = lowerOf(m);
  PardisoArrays p{l.pattern.outer, l.pattern.inner, l.values};
  for (int& v : p.ia) ++v;
  for (int& v : p.ja) ++v;
  return p;
}

TEST(PardisoInterface, FollowsIpoptsPhasesAndReportsTheInertia) {
  const AugmentedSystem sys = randomAugmentedSystem(11);
  PardisoArrays p = pardisoArrays(sys.dense);
  void* pt[64];
  int iparm[64], error = 1, mtype = -2, solverKind = 0, one = 1, n = sys.n();
  double dparm[64];
  pardisoinit(pt, &mtype, &solverKind, iparm, dparm, &error);
  ASSERT_EQ(error, 0);
  iparm[7] = 2;  // refinement steps allowed (Ipopt's pardiso_max_iterative_refinement_steps)
  auto call = [&](int phase, double* b, int nrhs) {
    int perm = 0, msglvl = 0;
    double x = 0;
    pardiso(pt, &one, &one, &mtype, &phase, &n, p.a.data(), p.ia.data(), p.ja.data(), &perm, &nrhs,
            iparm, &msglvl, b, &x, &error, dparm);
  };
  call(11, nullptr, 0);
  ASSERT_EQ(error, 0);
  call(22, nullptr, 0);
  ASSERT_EQ(error, 0);
  EXPECT_EQ(iparm[22], negativeEigenvalues(sys.dense));
  EXPECT_EQ(iparm[21] + iparm[22], n);
  const Eigen::MatrixXd original = Eigen::MatrixXd::Random(n, 2);  // column-major
  Eigen::MatrixXd rhs = original;
  call(33, rhs.data(), 2);
  ASSERT_EQ(error, 0);
  for (int r = 0; r < 2; ++r)
    EXPECT_LT(backwardError(sys.dense, rhs.col(r), original.col(r)), 1e-14);
  call(-1, nullptr, 0);
  EXPECT_EQ(error, 0);
}

TEST(PardisoInterface, ASingularMatrixIsErrorMinusFourWhichIpoptTakesForSingular) {
  Eigen::Matrix3d m = Eigen::Matrix3d::Zero();  // two equal constraint rows
  m(0, 0) = 1.0;
  m(1, 0) = m(0, 1) = m(2, 0) = m(0, 2) = 1.0;
  PardisoArrays p = pardisoArrays(m);
  void* pt[64];
  int iparm[64], error = 0, mtype = -2, solverKind = 0, one = 1, zero = 0, n = 3, perm = 0;
  double dparm[64], b = 0, x = 0;
  pardisoinit(pt, &mtype, &solverKind, iparm, dparm, &error);
  auto call = [&](int phase) {
    pardiso(pt, &one, &one, &mtype, &phase, &n, p.a.data(), p.ia.data(), p.ja.data(), &perm, &zero,
            iparm, &zero, &b, &x, &error, dparm);
    return error;
  };
  ASSERT_EQ(call(11), 0);
  EXPECT_EQ(call(22), -4);  // IpPardisoSolverInterface.cpp: ERROR == -4 -> SYMSOLVER_SINGULAR
  EXPECT_EQ(call(-1), 0);
}

TEST(PardisoInterface, RefusesAnotherMatrixTypeAndAFactorizationBeforeTheAnalysis) {
  const PardisoArrays p = pardisoArrays(Eigen::Matrix2d::Identity());
  void* pt[64];
  int iparm[64], error = 0, mtype = -2, solverKind = 0, one = 1, zero = 0, n = 2, perm = 0;
  double dparm[64], b = 0, x = 0;
  pardisoinit(pt, &mtype, &solverKind, iparm, dparm, &error);
  int phase = 22;
  pardiso(pt, &one, &one, &mtype, &phase, &n, p.a.data(), p.ia.data(), p.ja.data(), &perm, &zero,
          iparm, &zero, &b, &x, &error, dparm);
  EXPECT_EQ(error, -1);
  int unsymmetric = 11;
  phase = 11;
  pardiso(pt, &one, &one, &unsymmetric, &phase, &n, p.a.data(), p.ia.data(), p.ja.data(), &perm,
          &zero, iparm, &zero, &b, &x, &error, dparm);
  EXPECT_EQ(error, -1);
}

}  // namespace
}  // namespace gaitopt::ocp::kkt
