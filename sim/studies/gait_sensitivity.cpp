#include "sim/studies/gait_sensitivity.hpp"

#include <cmath>
#include <stdexcept>

#include <Eigen/Dense>
#include <Eigen/Eigenvalues>

namespace gaitopt::sim {

Eigen::MatrixXd discreteLyapunov(const Eigen::MatrixXd& a, const Eigen::MatrixXd& q) {
  const Eigen::Index n = a.rows();
  if (a.cols() != n || q.rows() != n || q.cols() != n)
    throw std::invalid_argument("discreteLyapunov: A must be square and Q of its size");
  // vec(A^T W A) = (A^T (x) A^T) vec W for column-major vec.
  Eigen::MatrixXd k = Eigen::MatrixXd::Identity(n * n, n * n);
  for (Eigen::Index i = 0; i < n; ++i)
    for (Eigen::Index j = 0; j < n; ++j) k.block(i * n, j * n, n, n) -= a(j, i) * a.transpose();
  const Eigen::VectorXd w =
      k.partialPivLu().solve(Eigen::Map<const Eigen::VectorXd>(q.data(), n * n));
  return Eigen::Map<const Eigen::MatrixXd>(w.data(), n, n);
}

GaitSensitivity gaitSensitivity(const LinearisedGait& g) {
  const Eigen::Index n = g.a.rows();
  if (g.a.cols() != n || g.b.rows() != n || g.c.cols() != n || g.d.rows() != g.c.rows() ||
      g.d.cols() != g.b.cols())
    throw std::invalid_argument("gaitSensitivity: A n x n, B n x q, C p x n, D p x q expected");
  if (n > 0 &&
      Eigen::EigenSolver<Eigen::MatrixXd>(g.a, false).eigenvalues().cwiseAbs().maxCoeff() >= 1)
    throw std::invalid_argument("gaitSensitivity: a multiplier on or outside the unit circle");
  GaitSensitivity s;
  s.per_indicator.resize(g.c.rows());
  for (Eigen::Index i = 0; i < g.c.rows(); ++i) {
    const Eigen::MatrixXd ci = g.c.row(i);
    const Eigen::MatrixXd w = discreteLyapunov(g.a, ci.transpose() * ci);
    s.per_indicator(i) = std::sqrt(g.d.row(i).squaredNorm() + (g.b.transpose() * w * g.b).trace());
  }
  s.norm = s.per_indicator.norm();
  return s;
}

}  // namespace gaitopt::sim
