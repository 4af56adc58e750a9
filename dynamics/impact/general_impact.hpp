#pragma once
/// @file general_impact.hpp
/// The impact of a planar chain whose contacts may be dependent: Mu (2004) sec. 2.4, the general
/// m-link impact (2.62) D (qdot+ - qdot-) = J^T F, J qdot+ = 0, for constraints J (2k x n) of
/// any rank r. With J of full rank it is (2.63-2.64). When r < 2k (more constraints than the
/// chain can feel, or two contacts on one link: Mu's three-link example, 2.79-2.82) any r
/// independent rows J1 of J span its row space (2.65-2.70), and
///   qdot+ = qdot- - D^-1 J1^T (J1 D^-1 J1^T)^-1 J1 qdot-                       (2.71)
/// is unique whatever rows are taken (2.72-2.74); the impulses F are not: 2k - r of their
/// components stay free (2.75-2.78, 2.88) until other equations fix them. Here J1 is the
/// orthonormal basis of the row space from a column-pivoted QR of J^T, and F is reported as the
/// least-norm impulse with J^T F equal to the generalised impulse D (qdot+ - qdot-).
#include "dynamics/model.hpp"

namespace gaitopt::dynamics {

struct GeneralImpact {
  Eigen::VectorXd qdot_plus;  ///< generalised velocities after the impact
  Eigen::VectorXd impulses;   ///< the least-norm F (2k) with J^T F = D (qdot+ - qdot-)
  int rank = 0;               ///< r, the rank of J
  int undetermined = 0;       ///< 2k - r impulse components the impact leaves free
};

/// @param mass_matrix D (n x n), symmetric positive definite
/// @param constraints J (m x n) of the contacts held after the impact
/// @param qdot_minus  generalised velocities before the impact
/// @param tolerance   relative size below which a pivot of the QR counts as zero (rank)
/// @throws std::invalid_argument for mismatched sizes
GeneralImpact generalImpact(const Eigen::MatrixXd& mass_matrix, const Eigen::MatrixXd& constraints,
                            const Eigen::VectorXd& qdot_minus, double tolerance = 1e-10);

}  // namespace gaitopt::dynamics
