#include "ocp/biped_dynamics.hpp"

#include "dynamics/residual_derivatives.hpp"

namespace gaitopt::ocp {
namespace {

dynamics::DynamicsPoint unpack(const Eigen::VectorXd& v, int n, bool dsp) {
  dynamics::DynamicsPoint x{v.segment(0, n), v.segment(n, n), v.segment(2 * n, n),
                            v.segment(3 * n, n)};
  if (dsp) x.lambda = v.segment<2>(4 * n);
  return x;
}

}  // namespace

BipedDynamics::BipedDynamics(const dynamics::Model& model, bool dsp)
    : model_(&model), dsp_(dsp), n_(model.nLinks()) {}

int BipedDynamics::rows() const {
  return dynamics::residualRows(*model_, dsp_);
}

void BipedDynamics::evaluate(const Eigen::VectorXd& v, Eigen::Ref<Eigen::VectorXd> f) const {
  f = dynamics::residual(*model_, unpack(v, n_, dsp_), dsp_);
}

void BipedDynamics::jacobian(const Eigen::VectorXd& v, Eigen::Ref<Eigen::MatrixXd> jac) const {
  // The point may carry more variables (work slacks) after the residual's own.
  const Eigen::MatrixXd rj = dynamics::residualJacobian(*model_, unpack(v, n_, dsp_), dsp_);
  jac.setZero();
  jac.leftCols(rj.cols()) = rj;
}

void BipedDynamics::hessian(const Eigen::VectorXd& v, const Eigen::VectorXd& weights,
                            Eigen::Ref<Eigen::MatrixXd> hess) const {
  const Eigen::MatrixXd rh = dynamics::residualHessian(*model_, unpack(v, n_, dsp_), dsp_, weights);
  hess.setZero();
  hess.topLeftCorner(rh.rows(), rh.cols()) = rh;
}

}  // namespace gaitopt::ocp
