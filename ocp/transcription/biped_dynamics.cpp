#include "ocp/transcription/biped_dynamics.hpp"

#include "dynamics/residual_derivatives.hpp"

namespace gaitopt::ocp {
namespace {

dynamics::DynamicsPoint unpack(const Eigen::VectorXd& v, const PointLayout& l) {
  dynamics::DynamicsPoint point{l.q.of(v), l.v.of(v), l.a.of(v), l.u.of(v)};
  if (l.hasContactForce()) point.lambda = l.lambda.of(v);
  return point;
}

}  // namespace

BipedDynamics::BipedDynamics(const dynamics::Model& model, const PointLayout& point)
    : model_(&model),
      point_(point),
      rows_(dynamics::residualRows(model, point.hasContactForce())) {}

int BipedDynamics::rows() const {
  return rows_;
}

void BipedDynamics::evaluate(const Eigen::VectorXd& v, Eigen::Ref<Eigen::VectorXd> f) const {
  f = dynamics::residual(*model_, unpack(v, point_), point_.hasContactForce()).head(rows_);
}

void BipedDynamics::jacobian(const Eigen::VectorXd& v, Eigen::Ref<Eigen::MatrixXd> jac) const {
  // The point may carry more variables (work slacks) after the residual's own.
  const Eigen::MatrixXd rj =
      dynamics::residualJacobian(*model_, unpack(v, point_), point_.hasContactForce());
  jac.setZero();
  jac.leftCols(rj.cols()) = rj.topRows(rows_);
}

void BipedDynamics::hessian(const Eigen::VectorXd& v, const Eigen::VectorXd& weights,
                            Eigen::Ref<Eigen::MatrixXd> hess) const {
  // Rows left out weigh nothing.
  Eigen::VectorXd all =
      Eigen::VectorXd::Zero(dynamics::residualRows(*model_, point_.hasContactForce()));
  all.head(rows_) = weights;
  const Eigen::MatrixXd rh =
      dynamics::residualHessian(*model_, unpack(v, point_), point_.hasContactForce(), all);
  hess.setZero();
  hess.topLeftCorner(rh.rows(), rh.cols()) = rh;
}

}  // namespace gaitopt::ocp
