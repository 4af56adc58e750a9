#include "dynamics/residual_derivatives.hpp"

#include <cmath>

#include "dynamics/dsp_dynamics.hpp"

namespace gaitopt::dynamics {
namespace {

/// Column offsets of the variable blocks in z.
struct Layout {
  int n;
  int th(int j) const { return j; }
  int dth(int j) const { return n + j; }
  int ddth(int j) const { return 2 * n + j; }
  int tau(int j) const { return 3 * n + j; }
  int lam(int k) const { return 4 * n + k; }
};

/// Adds v to h(r, c) and h(c, r) (once on the diagonal).
void addSym(Eigen::MatrixXd& h, int r, int c, double v) {
  h(r, c) += v;
  if (r != c) h(c, r) += v;
}

}  // namespace

int residualRows(const Model& model, bool dsp) {
  return model.nLinks() + (dsp ? 2 : 0);
}
int residualCols(const Model& model, bool dsp) {
  return 4 * model.nLinks() + (dsp ? 2 : 0);
}

Eigen::VectorXd residual(const Model& model, const DynamicsPoint& x, bool dsp) {
  if (dsp) return dspResidual(model, x.theta, x.dtheta, x.ddtheta, x.tau, x.lambda);
  return sspResidual(model, x.theta, x.dtheta, x.ddtheta, x.tau);
}

Eigen::MatrixXd residualJacobian(const Model& model, const DynamicsPoint& x, bool dsp) {
  const int n = model.nLinks();
  const Layout z{n};
  const auto& p = model.inertiaCoefficients();
  const auto& g = model.gravityCoefficients();
  const auto& th = x.theta;
  Eigen::MatrixXd jac = Eigen::MatrixXd::Zero(residualRows(model, dsp), residualCols(model, dsp));
  for (int i = 0; i < n; ++i) {
    jac(i, z.ddth(i)) = p(i, i);
    // dG_i/dtheta_i of G_i = -g_i sin(theta_i - gamma) (Mu 2.8c, sign corrected, sloped).
    jac(i, z.th(i)) = -g(i) * std::cos(th(i) - model.slope());
    for (int j = 0; j < n; ++j) {
      if (j == i) continue;
      const double c = std::cos(th(i) - th(j));
      const double s = std::sin(th(i) - th(j));
      const double e = p(i, j) * (-s * x.ddtheta(j) + c * x.dtheta(j) * x.dtheta(j));
      jac(i, z.ddth(j)) = p(i, j) * c;
      jac(i, z.dth(j)) = 2 * p(i, j) * s * x.dtheta(j);
      jac(i, z.th(i)) += e;
      jac(i, z.th(j)) -= e;
    }
  }
  // -M^T tau (2.43): constant.
  jac.block(0, z.tau(0), n, n) = -jointMap(n).transpose();
  if (!dsp) return jac;

  const auto& w = model.tipWeights();
  for (int i = 0; i < n; ++i) {
    const double c = std::cos(th(i));
    const double s = std::sin(th(i));
    // -J^T lambda (2.11).
    jac(i, z.th(i)) += w(i) * (s * x.lambda(0) + c * x.lambda(1));
    jac(i, z.lam(0)) = -w(i) * c;
    jac(i, z.lam(1)) = w(i) * s;
    // J ddtheta + Jdot dtheta.
    const double d2 = x.dtheta(i) * x.dtheta(i);
    jac(n, z.th(i)) = w(i) * (-s * x.ddtheta(i) - c * d2);
    jac(n + 1, z.th(i)) = w(i) * (-c * x.ddtheta(i) + s * d2);
    jac(n, z.dth(i)) = -2 * w(i) * s * x.dtheta(i);
    jac(n + 1, z.dth(i)) = -2 * w(i) * c * x.dtheta(i);
    jac(n, z.ddth(i)) = w(i) * c;
    jac(n + 1, z.ddth(i)) = -w(i) * s;
  }
  return jac;
}

Eigen::MatrixXd residualHessian(const Model& model, const DynamicsPoint& x, bool dsp,
                                const Eigen::VectorXd& sigma) {
  const int n = model.nLinks();
  const Layout z{n};
  const auto& p = model.inertiaCoefficients();
  const auto& g = model.gravityCoefficients();
  const auto& th = x.theta;
  const int cols = residualCols(model, dsp);
  Eigen::MatrixXd h = Eigen::MatrixXd::Zero(cols, cols);
  for (int i = 0; i < n; ++i) {
    const double si = sigma(i);
    h(z.th(i), z.th(i)) += si * g(i) * std::sin(th(i) - model.slope());  // d2G_i/dtheta_i^2
    for (int j = 0; j < n; ++j) {
      if (j == i) continue;
      // T = p_ij (cos(phi) ddtheta_j + sin(phi) dtheta_j^2), phi = theta_i - theta_j.
      const double c = std::cos(th(i) - th(j));
      const double s = std::sin(th(i) - th(j));
      const double t = p(i, j) * (c * x.ddtheta(j) + s * x.dtheta(j) * x.dtheta(j));
      addSym(h, z.th(i), z.th(i), -si * t);
      addSym(h, z.th(j), z.th(j), -si * t);
      addSym(h, z.th(i), z.th(j), si * t);
      addSym(h, z.th(i), z.ddth(j), -si * p(i, j) * s);
      addSym(h, z.th(j), z.ddth(j), si * p(i, j) * s);
      addSym(h, z.th(i), z.dth(j), 2 * si * p(i, j) * c * x.dtheta(j));
      addSym(h, z.th(j), z.dth(j), -2 * si * p(i, j) * c * x.dtheta(j));
      addSym(h, z.dth(j), z.dth(j), 2 * si * p(i, j) * s);
    }
  }
  if (!dsp) return h;

  const auto& w = model.tipWeights();
  const double sx = sigma(n);
  const double sy = sigma(n + 1);
  for (int i = 0; i < n; ++i) {
    const double c = std::cos(th(i));
    const double s = std::sin(th(i));
    const double si = sigma(i);
    const double d2 = x.dtheta(i) * x.dtheta(i);
    // -J^T lambda rows.
    addSym(h, z.th(i), z.th(i), si * w(i) * (c * x.lambda(0) - s * x.lambda(1)));
    addSym(h, z.th(i), z.lam(0), si * w(i) * s);
    addSym(h, z.th(i), z.lam(1), si * w(i) * c);
    // Constraint-acceleration rows.
    addSym(h, z.th(i), z.th(i),
           sx * w(i) * (-c * x.ddtheta(i) + s * d2) + sy * w(i) * (s * x.ddtheta(i) + c * d2));
    addSym(h, z.th(i), z.ddth(i), -sx * w(i) * s - sy * w(i) * c);
    addSym(h, z.th(i), z.dth(i),
           -2 * sx * w(i) * c * x.dtheta(i) + 2 * sy * w(i) * s * x.dtheta(i));
    addSym(h, z.dth(i), z.dth(i), -2 * sx * w(i) * s - 2 * sy * w(i) * c);
  }
  return h;
}

}  // namespace gaitopt::dynamics
