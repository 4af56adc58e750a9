#include "ocp/biped_dynamics.hpp"

#include "dynamics/residual_derivatives.hpp"

namespace gaitopt::ocp {
namespace {

dynamics::DynamicsPoint unpack(const Eigen::VectorXd& v, int n, bool dsp) {
  dynamics::DynamicsPoint x{v.segment(0, n), v.segment(n, n), v.segment(3 * n, n),
                            v.segment(4 * n, n)};
  if (dsp) x.lambda = v.segment<2>(5 * n);
  return x;
}

}  // namespace

BipedDynamics::BipedDynamics(const dynamics::Model& model, bool dsp)
    : model_(&model), dsp_(dsp), n_(model.nLinks()) {}

int BipedDynamics::rows() const {
  return n_ + dynamics::residualRows(*model_, dsp_);
}

void BipedDynamics::evaluate(const Eigen::VectorXd& v, Eigen::Ref<Eigen::VectorXd> f) const {
  f.head(n_) = v.segment(2 * n_, n_) - v.segment(n_, n_);
  f.tail(rows() - n_) = dynamics::residual(*model_, unpack(v, n_, dsp_), dsp_);
}

void BipedDynamics::jacobian(const Eigen::VectorXd& v, Eigen::Ref<Eigen::MatrixXd> jac) const {
  jac.setZero();
  for (int i = 0; i < n_; ++i) {
    jac(i, 2 * n_ + i) = 1;
    jac(i, n_ + i) = -1;
  }
  const Eigen::MatrixXd rj = dynamics::residualJacobian(*model_, unpack(v, n_, dsp_), dsp_);
  for (int j = 0; j < rj.cols(); ++j) jac.block(n_, column(j), rj.rows(), 1) = rj.col(j);
}

void BipedDynamics::hessian(const Eigen::VectorXd& v, const Eigen::VectorXd& weights,
                            Eigen::Ref<Eigen::MatrixXd> hess) const {
  hess.setZero();  // the kinematic rows are linear
  const Eigen::MatrixXd rh =
      dynamics::residualHessian(*model_, unpack(v, n_, dsp_), dsp_, weights.tail(rows() - n_));
  for (int c = 0; c < rh.cols(); ++c)
    for (int r = 0; r < rh.rows(); ++r) hess(column(r), column(c)) = rh(r, c);
}

}  // namespace gaitopt::ocp
