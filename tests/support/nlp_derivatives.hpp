#pragma once
/// Contract check of a whole Nlp: its sparse Jacobian and Lagrangian Hessian against central
/// differences of its own values and gradients, at a perturbed initial guess.
#include <Eigen/Dense>
#include <Eigen/SparseCore>

#include "ocp/transcription/nlp.hpp"

namespace gaitopt::test {

struct DerivativeErrors {
  double jacobian = 0;  ///< ||FD - exact||_F / ||exact||_F
  double hessian = 0;
  double gradient = 0;  ///< of the cost
};

inline Eigen::MatrixXd denseOf(const ocp::Triplets& t, int rows, int cols) {
  Eigen::SparseMatrix<double> m(rows, cols);
  m.setFromTriplets(t.begin(), t.end());
  return Eigen::MatrixXd(m);
}

inline DerivativeErrors compareWithCentralDifferences(const ocp::Nlp& nlp, double perturbation) {
  const int n = nlp.variables(), m = nlp.constraints();
  std::srand(3);
  const Eigen::VectorXd x = nlp.initialGuess() + perturbation * Eigen::VectorXd::Random(n);
  const Eigen::VectorXd lambda = Eigen::VectorXd::Random(m);
  const double sigma = 0.3;
  const Eigen::MatrixXd jac = denseOf(nlp.jacobianTriplets(x), m, n);
  const Eigen::MatrixXd hess =
      denseOf(nlp.hessianTriplets(x, sigma, lambda), n, n).selfadjointView<Eigen::Lower>();
  auto gradient = [&](const Eigen::VectorXd& z) -> Eigen::VectorXd {
    return sigma * nlp.costGradient(z) +
           denseOf(nlp.jacobianTriplets(z), m, n).transpose() * lambda;
  };
  Eigen::MatrixXd fd_jac(m, n), fd_hess(n, n);
  Eigen::VectorXd fd_grad(n);
  const double h = 1e-6;
  for (int k = 0; k < n; ++k) {
    Eigen::VectorXd xp = x, xm = x;
    xp(k) += h;
    xm(k) -= h;
    fd_jac.col(k) = (nlp.constraintValues(xp) - nlp.constraintValues(xm)) / (2 * h);
    fd_hess.col(k) = (gradient(xp) - gradient(xm)) / (2 * h);
    fd_grad(k) = (nlp.cost(xp) - nlp.cost(xm)) / (2 * h);
  }
  const Eigen::VectorXd grad = nlp.costGradient(x);
  return {(fd_jac - jac).norm() / jac.norm(), (fd_hess - hess).norm() / hess.norm(),
          (fd_grad - grad).norm() / grad.norm()};
}

}  // namespace gaitopt::test
