// The transcription layer on a problem with a known answer: minimum-effort motion of a double
// integrator, x'' = u, x(0) = 0, x'(0) = 0, x(1) = 1, x'(1) = 0, cost integral of u^2.
// Exact solution u = 6 - 12 t, x = 3 t^2 - 2 t^3, cost 12. Hermite-Simpson represents the cubic
// exactly; trapezoidal converges with order 2. Derivatives of every set against differences.
#include <gtest/gtest.h>

#include <cmath>

#include "ocp/collocation.hpp"
#include "ocp/ipopt_adapter.hpp"
#include "ocp/point_function.hpp"

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

Nlp buildProblem(const PhaseLayout& layout) {
  Nlp nlp;
  const int n = layout.variables();
  const double inf = 1e20;
  Eigen::VectorXd lo = Eigen::VectorXd::Constant(n, -inf), hi = Eigen::VectorXd::Constant(n, inf);
  const int last = layout.points() - 1;
  lo(layout.x(0, 0)) = hi(layout.x(0, 0)) = 0;  // boundary conditions as bounds (ifopt style)
  lo(layout.x(0, 1)) = hi(layout.x(0, 1)) = 0;
  lo(layout.x(last, 0)) = hi(layout.x(last, 0)) = 1;
  lo(layout.x(last, 1)) = hi(layout.x(last, 1)) = 0;
  nlp.addVariables("points", n, lo, hi, Eigen::VectorXd::Zero(n));
  nlp.addConstraint(std::make_unique<CollocationDefects>(layout));
  nlp.addConstraint(
      std::make_unique<PathConstraint>("dynamics", layout, std::make_shared<DoubleIntegrator>()));
  nlp.addCost(std::make_unique<QuadratureCost>("effort", layout, std::make_shared<Effort>()));
  return nlp;
}

PhaseLayout layoutFor(Scheme scheme, int segments) {
  return PhaseLayout{scheme, segments, 1.0, 2, 1, 0, 0};
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

TEST(DoubleIntegrator, JacobianAndHessianEqualCentralDifferences) {
  for (Scheme scheme : {Scheme::kTrapezoidal, Scheme::kHermiteSimpson}) {
    const Nlp nlp = buildProblem(layoutFor(scheme, 4));
    const int n = nlp.variables();
    const Eigen::VectorXd x = Eigen::VectorXd::Random(n);
    const Eigen::VectorXd lambda = Eigen::VectorXd::Random(nlp.constraints());
    Eigen::SparseMatrix<double> jac(nlp.constraints(), n), hess(n, n);
    const Triplets jt = nlp.jacobianTriplets(x), ht = nlp.hessianTriplets(x, 0.7, lambda);
    jac.setFromTriplets(jt.begin(), jt.end());
    hess.setFromTriplets(ht.begin(), ht.end());
    const Eigen::MatrixXd h_full = Eigen::MatrixXd(hess).selfadjointView<Eigen::Lower>();
    const double step = 1e-6;
    for (int k = 0; k < n; ++k) {
      Eigen::VectorXd xp = x, xm = x;
      xp(k) += step;
      xm(k) -= step;
      const Eigen::VectorXd dg = (nlp.constraintValues(xp) - nlp.constraintValues(xm)) / (2 * step);
      EXPECT_LT((dg - Eigen::MatrixXd(jac).col(k)).norm(), 1e-7);
      const Eigen::VectorXd dgrad =
          0.7 * (nlp.costGradient(xp) - nlp.costGradient(xm)) / (2 * step);
      EXPECT_LT((dgrad - h_full.col(k)).norm(), 1e-6);  // constraints are linear here
    }
  }
}

}  // namespace
}  // namespace gaitopt::ocp
