#pragma once
/// @file biped_dynamics.hpp
/// The biped's dynamics as a collocation path constraint, on points of the second-order layout
/// (point_layout.hpp) v = [theta, dtheta, ddtheta, tau (, lambda) (, work slacks)]: joint
/// torques in q-space, lambda the ground force at E (DSP only). Rows:
///   SSP: D ddtheta + H dtheta + G - M^T tau = 0           (Mu 2.7, 2.43)
///   DSP: ... - J^T lambda = 0 and J ddtheta + Jdot dtheta = 0   (Mu 2.11, 2.9)
/// Derivatives are the analytic ones of dynamics/residual_derivatives.hpp.
#include "dynamics/model.hpp"
#include "ocp/transcription/point_function.hpp"
#include "ocp/transcription/point_layout.hpp"

namespace gaitopt::ocp {

class BipedDynamics : public PointFunction {
 public:
  /// The point carries lambda (and the DSP rows apply) when `point` has a contact force.
  BipedDynamics(const dynamics::Model& model, const PointLayout& point);
  int rows() const override;
  void evaluate(const Eigen::VectorXd& v, Eigen::Ref<Eigen::VectorXd> f) const override;
  void jacobian(const Eigen::VectorXd& v, Eigen::Ref<Eigen::MatrixXd> jac) const override;
  void hessian(const Eigen::VectorXd& v, const Eigen::VectorXd& weights,
               Eigen::Ref<Eigen::MatrixXd> hess) const override;

 private:
  const dynamics::Model* model_;
  PointLayout point_;
  int rows_;
};

}  // namespace gaitopt::ocp
