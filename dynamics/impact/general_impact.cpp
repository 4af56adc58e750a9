#include "dynamics/impact/general_impact.hpp"

#include <stdexcept>

#include <Eigen/Cholesky>
#include <Eigen/QR>

namespace gaitopt::dynamics {

GeneralImpact generalImpact(const Eigen::MatrixXd& mass_matrix, const Eigen::MatrixXd& constraints,
                            const Eigen::VectorXd& qdot_minus, double tolerance) {
  const auto n = mass_matrix.rows();
  if (mass_matrix.cols() != n || constraints.cols() != n || qdot_minus.size() != n)
    throw std::invalid_argument("generalImpact: D must be n x n, J m x n and qdot- of size n");
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(constraints.transpose());
  qr.setThreshold(tolerance);
  GeneralImpact out;
  out.rank = static_cast<int>(qr.rank());
  out.undetermined = static_cast<int>(constraints.rows()) - out.rank;
  // J1: an orthonormal basis of J's row space, r x n (2.65-2.70).
  const Eigen::MatrixXd q = qr.householderQ() * Eigen::MatrixXd::Identity(n, out.rank);
  const Eigen::MatrixXd j1 = q.transpose();
  const auto d = mass_matrix.ldlt();
  const Eigen::MatrixXd d_inv_j1t = d.solve(j1.transpose());
  const Eigen::VectorXd f1 = (j1 * d_inv_j1t).ldlt().solve(-(j1 * qdot_minus));  // (2.70)
  out.qdot_plus = qdot_minus + d_inv_j1t * f1;                                   // (2.71)
  // The generalised impulse D (qdot+ - qdot-) = J1^T F1 lies in J's row space: the least-norm
  // F with J^T F equal to it.
  out.impulses = constraints.transpose().completeOrthogonalDecomposition().solve(
      Eigen::VectorXd(j1.transpose() * f1));
  return out;
}

}  // namespace gaitopt::dynamics
