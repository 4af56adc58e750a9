#include "ocp/gait_costs.hpp"

namespace gaitopt::ocp {
namespace {
constexpr double kInf = 1e20;  // Ipopt's infinity (nlp_upper_bound_inf)
}

void TorqueSquared::evaluate(const Eigen::VectorXd& v, Eigen::Ref<Eigen::VectorXd> f) const {
  f(0) = v.segment(3 * n_, n_).squaredNorm();
}

void TorqueSquared::jacobian(const Eigen::VectorXd& v, Eigen::Ref<Eigen::MatrixXd> jac) const {
  jac.setZero();
  jac.block(0, 3 * n_, 1, n_) = 2 * v.segment(3 * n_, n_).transpose();
}

void TorqueSquared::hessian(const Eigen::VectorXd&, const Eigen::VectorXd& w,
                            Eigen::Ref<Eigen::MatrixXd> hess) const {
  hess.setZero();
  hess.block(3 * n_, 3 * n_, n_, n_).diagonal().setConstant(2 * w(0));
}

void KneeDirection::evaluate(const Eigen::VectorXd& v, Eigen::Ref<Eigen::VectorXd> f) const {
  f << v(0) - v(1), v(n_ - 2) - v(n_ - 1);
}

void KneeDirection::jacobian(const Eigen::VectorXd&, Eigen::Ref<Eigen::MatrixXd> jac) const {
  jac.setZero();
  jac(0, 0) = 1;
  jac(0, 1) = -1;
  jac(1, n_ - 2) = 1;
  jac(1, n_ - 1) = -1;
}

Eigen::VectorXd KneeDirection::lowerBounds() const {
  return Eigen::Vector2d(0, -kInf);
}
Eigen::VectorXd KneeDirection::upperBounds() const {
  return Eigen::Vector2d(kInf, 0);
}

}  // namespace gaitopt::ocp
