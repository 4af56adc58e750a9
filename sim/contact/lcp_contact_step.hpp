#pragma once
/// @file lcp_contact_step.hpp
/// One step of velocity-level time stepping with rigid unilateral contacts and Coulomb friction
/// (Stewart & Trinkle 1996; Anitescu & Potra 1997), the time-stepping form of the impact LCP of
/// Addi & Rodic (2010) eqs. (36), (43), (45), (56): the same complementarity laws imposed on
/// impulses over a step h instead of over an impact. Generic in the mechanical system: it sees
/// only the mass matrix, the non-contact force and per-contact Jacobian rows. Planar: the
/// friction cone of each contact is the pyramid of the two directions +t and -t.
#include <vector>

#include <Eigen/Core>

#include "sim/contact/lemke.hpp"

namespace gaitopt::sim {

/// One point contact as seen from the generalised velocities v (nq).
struct ContactRows {
  Eigen::RowVectorXd normal;   ///< n (1 x nq): normal separation speed = n v [m/s]
  Eigen::RowVectorXd tangent;  ///< t (1 x nq): tangential slip speed = t v [m/s]
  double gap;                  ///< phi [m]: >= 0 when separated, < 0 when penetrating
  double friction;             ///< Coulomb coefficient mu >= 0 [-]
};

struct LcpStepResult {
  LemkeStatus status = LemkeStatus::kRayTermination;
  Eigen::VectorXd velocity;            ///< v_next (nq); NaN unless status is kSolved
  Eigen::VectorXd normal_impulse;      ///< p_n per contact [N s] (>= 0); NaN unless kSolved
  Eigen::VectorXd tangential_impulse;  ///< p_t per contact along +t [N s]; NaN unless kSolved
  int pivots = 0;                      ///< Lemke pivots
};

/// Solves for v_next and the contact impulses over one step of length h:
///   M (v_next - v) = h f + sum_i (n_i^T p_n,i + t_i^T (beta+_i - beta-_i))
///   0 <= p_n,i  _|_  n_i v_next + phi_i / h >= 0      (non-penetration at the step's end)
///   0 <= beta+_i _|_ lambda_i + t_i v_next >= 0        (beta+ acts only against slip along -t)
///   0 <= beta-_i _|_ lambda_i - t_i v_next >= 0
///   0 <= lambda_i _|_ mu_i p_n,i - beta+_i - beta-_i >= 0  (lambda = |slip speed| on the cone)
/// The phi / h term (gap stabilisation) lets a separated contact close exactly at the end of
/// the step and pushes a penetrated one out, so resting contact neither sinks nor drifts.
/// The caller integrates positions with v_next (semi-implicit Euler, q_next = q + h v_next).
/// @param mass      M, nq x nq, symmetric positive definite (the lower triangle is read)
/// @param force     f = tau - C qdot - G, nq: every generalised force except contact [N, N m]
/// @param velocity  v at the start of the step, nq
/// @param step      h > 0 [s]
/// @throws std::invalid_argument on a size mismatch, a non-finite input, h <= 0, mu < 0, or a
///         mass matrix that is not positive definite. An LCP Lemke cannot solve is reported in
///         `status`, not thrown.
LcpStepResult lcpContactStep(const Eigen::MatrixXd& mass, const Eigen::VectorXd& force,
                             const Eigen::VectorXd& velocity, double step,
                             const std::vector<ContactRows>& contacts,
                             const LemkeOptions& options = {});

}  // namespace gaitopt::sim
