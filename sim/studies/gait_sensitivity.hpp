#pragma once
/// @file gait_sensitivity.hpp
/// The gait sensitivity norm (Hobbelen and Wisse 2007, "A disturbance rejection measure for limit
/// cycle walkers: the gait sensitivity norm", IEEE T-RO 23(6)): how much a unit disturbance at
/// one step shows in chosen gait indicators over all the steps after it. With the return map
/// linearised at its fixed point,
///   x_{k+1} = A x_k + B d_k,   e_k = C x_k + D d_k,
/// (x the state at the Poincare section, d the disturbance, e the indicators' departure from the
/// gait's), a unit disturbance at step 0 from the fixed point gives e_0 = D and
/// e_k = C A^{k-1} B (k >= 1), so
///   GSN^2 = sum_k |e_k|^2 = |D|_F^2 + trace(B^T W B),   W = A^T W A + C^T C,
/// W the observability Gramian (a discrete Lyapunov equation); the sum converges when every
/// multiplier of A lies inside the unit circle. Indicators with different units are summed as
/// they are (Hobbelen and Wisse do the same); per-indicator norms are reported beside the total.
#include <Eigen/Core>

namespace gaitopt::sim {

struct LinearisedGait {
  Eigen::MatrixXd a;  ///< dx_{k+1}/dx_k, n x n
  Eigen::MatrixXd b;  ///< dx_{k+1}/dd_k, n x q
  Eigen::MatrixXd c;  ///< de_k/dx_k, p x n
  Eigen::MatrixXd d;  ///< de_k/dd_k, p x q
};

struct GaitSensitivity {
  double norm = 0;                ///< GSN, the total
  Eigen::VectorXd per_indicator;  ///< each indicator's own norm (size p); squares sum to norm^2
};

/// W solving W = A^T W A + Q, by its Kronecker form (I - A^T (x) A^T) vec W = vec Q.
/// @throws std::invalid_argument when A is not square or Q not of A's size.
Eigen::MatrixXd discreteLyapunov(const Eigen::MatrixXd& a, const Eigen::MatrixXd& q);

/// The GSN of `gait`.
/// @throws std::invalid_argument for mismatched sizes, or when A has a multiplier with
///         |lambda| >= 1 (the disturbance never dies out: the norm is infinite).
GaitSensitivity gaitSensitivity(const LinearisedGait& gait);

}  // namespace gaitopt::sim
