// The transcription layer on a problem with a known answer: minimum-effort motion of a double
// integrator, x'' = u, x(0) = 0, x'(0) = 0, x(1) = 1, x'(1) = 0, cost integral of u^2.
// Exact solution u = 6 - 12 t, x = 3 t^2 - 2 t^3, cost 12. Hermite-Simpson represents the cubic
// exactly; trapezoidal converges with order 2. Derivatives of every set against differences.
#include <gtest/gtest.h>

#include <cmath>

#include "ocp/solve/ipopt_adapter.hpp"
#include "ocp/transcription/collocation.hpp"
#include "ocp/transcription/collocation_interpolation.hpp"
#include "ocp/transcription/mesh_refinement.hpp"
#include "ocp/transcription/point_function.hpp"
#include "support/nlp_derivatives.hpp"

namespace gaitopt::ocp {
namespace {

/// F(x, xdot, u) = (xdot_0 - x_1, xdot_1 - u): the implicit double-integrator dynamics.
class DoubleIntegrator : public PointFunction {
 public:
  int rows() const override { return 2; }
  void evaluate(const Eigen::VectorXd& v, Eigen::Ref<Eigen::VectorXd> f) const override {
    f << v(2) - v(1), v(3) - v(4);
  }
  void jacobian(const Eigen::VectorXd&, Eigen::Ref<Eigen::MatrixXd> jac) const override {
    jac << 0, -1, 1, 0, 0,  //
        0, 0, 0, 1, -1;
  }
  void hessian(const Eigen::VectorXd&, const Eigen::VectorXd&,
               Eigen::Ref<Eigen::MatrixXd> hess) const override {
    hess.setZero();
  }
};

/// L = u^2 (deliberately nonlinear so the cost Hessian is exercised).
class Effort : public PointFunction {
 public:
  int rows() const override { return 1; }
  void evaluate(const Eigen::VectorXd& v, Eigen::Ref<Eigen::VectorXd> f) const override {
    f(0) = v(4) * v(4);
  }
  void jacobian(const Eigen::VectorXd& v, Eigen::Ref<Eigen::MatrixXd> jac) const override {
    jac.setZero();
    jac(0, 4) = 2 * v(4);
  }
  void hessian(const Eigen::VectorXd&, const Eigen::VectorXd& w,
               Eigen::Ref<Eigen::MatrixXd> hess) const override {
    hess.setZero();
    hess(4, 4) = 2 * w(0);
  }
};

/// The problem on `layout`; with a free duration (layout.duration_index = 0, points at
/// offset 1) T is the first variable, within [0.5, 2].
Nlp buildProblem(const PhaseLayout& layout) {
  Nlp nlp;
  if (layout.freeDuration())
    nlp.addVariables("duration", 1, Eigen::VectorXd::Constant(1, 0.5),
                     Eigen::VectorXd::Constant(1, 2.0), Eigen::VectorXd::Constant(1, 1.0));
  const int n = layout.variables();
  Eigen::VectorXd lo = Eigen::VectorXd::Constant(n, -kInf), hi = Eigen::VectorXd::Constant(n, kInf);
  const int last = layout.points() - 1;
  auto fix = [&](int p, int i, double value) {  // boundary conditions as bounds (ifopt style)
    lo(layout.x(p, i) - layout.offset) = hi(layout.x(p, i) - layout.offset) = value;
  };
  fix(0, 0, 0);
  fix(0, 1, 0);
  fix(last, 0, 1);
  fix(last, 1, 0);
  nlp.addVariables("points", n, lo, hi, Eigen::VectorXd::Zero(n));
  nlp.addConstraint(std::make_unique<CollocationDefects>("defects", "move", layout));
  nlp.addConstraint(std::make_unique<PathConstraint>("dynamics", "move", layout,
                                                     std::make_shared<DoubleIntegrator>()));
  nlp.addCost(std::make_unique<QuadratureCost>("effort", layout, std::make_shared<Effort>()));
  return nlp;
}

PhaseLayout layoutFor(Scheme scheme, int segments) {
  return PhaseLayout{.scheme = scheme, .segments = segments, .duration = 1.0, .nx = 2, .nu = 1};
}

SolveResult solve(const PhaseLayout& layout) {
  const Nlp nlp = buildProblem(layout);
  SolverOptions options;
  options.tolerance = 1e-10;
  return solveWithIpopt(nlp, options);
}

TEST(DoubleIntegrator, HermiteSimpsonRecoversTheExactCubic) {
  const PhaseLayout layout = layoutFor(Scheme::kHermiteSimpson, 5);
  const SolveResult r = solve(layout);
  ASSERT_TRUE(r.success) << r.status;
  EXPECT_NEAR(r.cost, 12.0, 1e-7);
  for (int p = 0; p < layout.points(); ++p) {
    const double t = layout.time(p);
    EXPECT_NEAR(r.x(layout.x(p, 0)), 3 * t * t - 2 * t * t * t, 1e-8);
    EXPECT_NEAR(r.x(layout.u(p, 0)), 6 - 12 * t, 1e-7);
  }
  EXPECT_LT(r.max_violation, 1e-9);
  EXPECT_GT(r.iterations, 0);
}

/// Distinct (row, col) positions of `triplets`, merged by Eigen rather than by SparsityPattern.
int distinctEntries(const Triplets& triplets, int rows, int cols) {
  Eigen::SparseMatrix<double> m(rows, cols);
  m.setFromTriplets(triplets.begin(), triplets.end());
  return static_cast<int>(m.nonZeros());
}

TEST(DoubleIntegrator, SolveProfileCountsTheKktSystemAndOneFactorizationPerIteration) {
  const PhaseLayout layout = layoutFor(Scheme::kHermiteSimpson, 5);
  const Nlp nlp = buildProblem(layout);
  const SolveResult r = solveWithIpopt(nlp, SolverOptions{});
  ASSERT_TRUE(r.success) << r.status;
  const int n = nlp.variables(), m = nlp.constraints();  // equalities only: no slacks
  EXPECT_EQ(r.profile.kkt_dimension, n + m);
  const Eigen::VectorXd x = nlp.initialGuess(), ones = Eigen::VectorXd::Ones(m);
  EXPECT_EQ(r.profile.kkt_nonzeros, distinctEntries(nlp.jacobianTriplets(x), m, n) +
                                        distinctEntries(nlp.hessianTriplets(x, 1.0, ones), n, n) +
                                        n + m);
  // Every iteration solves with a fresh factorization, and the start needs one more (the
  // least-squares multipliers).
  EXPECT_GE(r.profile.factorizations, r.iterations + 1);
  EXPECT_GT(r.profile.linear_solver_time_s, 0);
  EXPECT_LT(r.profile.linear_solver_time_s + r.profile.sparsity_time_s, r.wall_time_s);
}

TEST(DoubleIntegrator, HermiteSimpsonIsExactOnAnUnequalMeshAndBetweenItsNodes) {
  PhaseLayout layout = layoutFor(Scheme::kHermiteSimpson, 4);
  layout.mesh = {0.0, 0.1, 0.45, 0.5, 1.0};
  const SolveResult r = solve(layout);
  ASSERT_TRUE(r.success) << r.status;
  EXPECT_NEAR(r.cost, 12.0, 1e-7);
  for (int j = 0; j <= 40; ++j) {  // the scheme's cubic state and quadratic control
    const double t = j / 40.0;
    const Eigen::VectorXd v = interpolatePoint(layout, r.x, t);
    EXPECT_NEAR(v(0), 3 * t * t - 2 * t * t * t, 1e-8) << t;
    EXPECT_NEAR(v(1), 6 * t - 6 * t * t, 1e-8) << t;
    EXPECT_NEAR(v(4), 6 - 12 * t, 1e-7) << t;
  }
}

TEST(DoubleIntegrator, FreeDurationReachesTheAnalyticOptimum) {
  // Effort 12 / T^3 over [0.5, 2] s: the optimum is the longest motion, T = 2, cost 1.5.
  PhaseLayout layout = layoutFor(Scheme::kHermiteSimpson, 5);
  layout.duration_index = 0;
  layout.offset = 1;
  const SolveResult r = solve(layout);
  ASSERT_TRUE(r.success) << r.status;
  EXPECT_NEAR(r.x(0), 2.0, 1e-6);
  EXPECT_NEAR(r.cost, 1.5, 1e-6);
  EXPECT_NEAR(interpolatePoint(layout, r.x, 1.0)(0), 0.5, 1e-8);  // x(T/2) = 1/2 by symmetry
}

TEST(DoubleIntegrator, SegmentErrorVanishesForHermiteSimpsonAndShrinksAsHCubedForTrapezoidal) {
  const DoubleIntegrator dynamics;
  const PhaseLayout hs = layoutFor(Scheme::kHermiteSimpson, 5);
  EXPECT_LT(segmentErrors(hs, dynamics, solve(hs).x).maxCoeff(), 1e-9);  // the exact cubic
  std::vector<double> worst;
  for (int segments : {8, 16}) {
    const PhaseLayout trap = layoutFor(Scheme::kTrapezoidal, segments);
    worst.push_back(segmentErrors(trap, dynamics, solve(trap).x).maxCoeff());
  }
  // Local error of an order-2 scheme: O(h^3) per segment.
  EXPECT_NEAR(worst[0] / worst[1], 8.0, 1.0) << worst[0] << " " << worst[1];
}

TEST(DoubleIntegrator, RefinedMeshSplitsEachSegmentByItsErrorRatio) {
  const PhaseLayout layout = layoutFor(Scheme::kHermiteSimpson, 4);
  Eigen::VectorXd errors(4);
  errors << 0.5, 2.0, 100.0, 1e5;  // tolerance 1: keep, then ceil(ratio^(1/5)) within [2, 4]
  const std::vector<double> mesh = refinedMesh(layout, errors, 1.0);
  const std::vector<double> expected{
      0, 0.25, 0.375, 0.5, 0.5 + 0.25 / 3, 0.5 + 0.5 / 3, 0.75, 0.8125, 0.875, 0.9375, 1.0};
  ASSERT_EQ(mesh.size(), expected.size());
  for (size_t i = 0; i < mesh.size(); ++i) EXPECT_NEAR(mesh[i], expected[i], 1e-15) << i;
}

TEST(DoubleIntegrator, TrapezoidalConvergesWithOrderTwo) {
  std::vector<double> errors;
  for (int segments : {8, 16, 32}) {
    const SolveResult r = solve(layoutFor(Scheme::kTrapezoidal, segments));
    ASSERT_TRUE(r.success) << r.status;
    errors.push_back(std::abs(r.cost - 12.0));
  }
  const double order = std::log2(errors[1] / errors[2]);
  EXPECT_NEAR(order, 2.0, 0.2) << "errors " << errors[0] << " " << errors[1] << " " << errors[2];
}

TEST(DoubleIntegrator, JacobianHessianAndGradientEqualCentralDifferences) {
  for (Scheme scheme : {Scheme::kTrapezoidal, Scheme::kHermiteSimpson}) {
    PhaseLayout layout = layoutFor(scheme, 4);
    layout.mesh = {0.0, 0.2, 0.3, 0.7, 1.0};
    layout.duration_index = 0;  // free T: bilinear defects and a scaled quadrature
    layout.offset = 1;
    const test::DerivativeErrors e = test::compareWithCentralDifferences(buildProblem(layout), 0.5);
    EXPECT_LT(e.jacobian, 1e-8) << toString(scheme);
    EXPECT_LT(e.hessian, 1e-7) << toString(scheme);
    EXPECT_LT(e.gradient, 1e-8) << toString(scheme);
  }
}

}  // namespace
}  // namespace gaitopt::ocp
