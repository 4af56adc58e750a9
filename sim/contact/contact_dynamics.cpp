#include "sim/contact/contact_dynamics.hpp"

#include <Eigen/Cholesky>
#include <Eigen/LU>

#include "dynamics/floating_base_dynamics.hpp"

namespace gaitopt::sim {
namespace {

/// The rows and columns one tip adds: constraint rows G (accelerations held at zero, with their
/// bias Jdot qdot) and force columns W (generalised force per multiplier).
struct ContactColumns {
  Eigen::MatrixXd g, w;
  Eigen::VectorXd bias;
  int count = 0;

  ContactColumns(int dofs, int max_rows) : g(max_rows, dofs), w(dofs, max_rows), bias(max_rows) {}

  void add(const Eigen::RowVectorXd& row, double row_bias, const Eigen::VectorXd& column) {
    g.row(count) = row;
    bias(count) = row_bias;
    w.col(count) = column;
    ++count;
  }
};

/// Adds the tip's normal row (and tangential row when it sticks); returns the multiplier index
/// of its normal force.
int addTip(ContactColumns& c, const TipContact& tip, const Eigen::MatrixXd& jac, const Vec2d& jdot,
           double mu) {
  const int normal = c.count;
  Eigen::VectorXd column = jac.row(1).transpose();
  if (tip.mode == TipContact::Mode::kSlide)
    column -= tip.direction * mu * jac.row(0).transpose();  // T = -mu N s (HGB 34)
  c.add(jac.row(1), jdot(1), column);
  if (tip.mode == TipContact::Mode::kStick) c.add(jac.row(0), jdot(0), jac.row(0).transpose());
  return normal;
}

Vec2d tipForce(const TipContact& tip, const Eigen::VectorXd& lambda, int normal, double mu) {
  if (!tip.onGround()) return Vec2d::Zero();
  const double n = lambda(normal);
  const double t =
      tip.mode == TipContact::Mode::kStick ? lambda(normal + 1) : -tip.direction * mu * n;
  return {t, n};
}

}  // namespace

ContactAcceleration contactDynamics(const dynamics::Model& plant, const VecD& theta,
                                    const VecD& dtheta, const VecD& tau, const ContactSet& contacts,
                                    const Vec2d& hip_force) {
  const dynamics::FloatingBaseDynamics fb = dynamics::floatingBaseDynamics(plant, theta, dtheta);
  const auto dofs = static_cast<int>(fb.mass.rows());
  Eigen::VectorXd rhs = dynamics::floatingBaseActuation(plant, tau) - fb.bias;
  if (!hip_force.isZero())
    rhs += dynamics::floatingJacobian(plant.hipWeights(), theta).transpose() * hip_force;
  ContactColumns c(dofs, 4);
  const double mu = plant.friction();
  int normal_b = -1, normal_e = -1;
  if (contacts.b.onGround()) normal_b = addTip(c, contacts.b, fb.jac_b, Vec2d::Zero(), mu);
  if (contacts.e.onGround()) normal_e = addTip(c, contacts.e, fb.jac_e, fb.jdot_e, mu);
  const auto ldlt = fb.mass.ldlt();
  ContactAcceleration out;
  if (c.count == 0) {
    out.qddot = ldlt.solve(rhs);
    return out;
  }
  const Eigen::MatrixXd g = c.g.topRows(c.count), w = c.w.leftCols(c.count);
  const Eigen::MatrixXd d_inv_w = ldlt.solve(w);
  const Eigen::VectorXd free_acc = ldlt.solve(rhs);
  // G qddot + bias = 0 with qddot = D^-1 (rhs + W lambda).
  const Eigen::VectorXd lambda =
      (g * d_inv_w).partialPivLu().solve(-c.bias.head(c.count) - g * free_acc);
  out.qddot = free_acc + d_inv_w * lambda;
  if (normal_b >= 0) out.force_b = tipForce(contacts.b, lambda, normal_b, mu);
  if (normal_e >= 0) out.force_e = tipForce(contacts.e, lambda, normal_e, mu);
  return out;
}

}  // namespace gaitopt::sim
