#pragma once
/// @file computed_torque_law.hpp
/// The closed loop's computed-torque law as the feedback that drives a model variant in single
/// support (shape_config.hpp, FeedbackGains::Law::kComputedTorque): the torque the controller
/// computes on its nominal model (sim/controllers/tracking_controller.cpp, Mu 2.43),
///   u_k = M^-T (D(theta_k) a_cmd + N(theta_k, dtheta_k)),
///   a_cmd = ddtheta_ref + kp (theta_ref - theta_k) + kd (dtheta_ref - dtheta_k),
/// where the joint-space PD of the controller, q = M theta (Mu 2.41), is the same PD on the
/// absolute angles because M is linear and invertible. The rows are the nominal's SSP residual
/// D a_cmd + N - M^T u_k = 0 (Mu 2.7): BipedDynamics on the point (theta_k, dtheta_k, a_cmd,
/// u_k), a linear map of the law's variables, so its exact derivatives carry over by the chain
/// rule (Jacobian J L, Hessian L^T H L).
#include <memory>
#include <string>
#include <vector>

#include "dynamics/model.hpp"
#include "ocp/shape/shape_config.hpp"
#include "ocp/transcription/biped_dynamics.hpp"
#include "ocp/transcription/nlp.hpp"
#include "ocp/transcription/phase.hpp"
#include "ocp/transcription/point_function.hpp"

namespace gaitopt::ocp {

/// y = (theta_k, dtheta_k, u_k, theta_ref, dtheta_ref, ddtheta_ref) (6 n) -> the n residuals.
class ComputedTorqueResidual : public PointFunction {
 public:
  /// @throws std::invalid_argument for a joint the nominal model does not actuate (the law
  ///         commands every joint)
  ComputedTorqueResidual(const dynamics::Model& nominal, const FeedbackGains& gains);
  int rows() const override { return n_; }
  void evaluate(const Eigen::VectorXd& y, Eigen::Ref<Eigen::VectorXd> f) const override;
  void jacobian(const Eigen::VectorXd& y, Eigen::Ref<Eigen::MatrixXd> jac) const override;
  void hessian(const Eigen::VectorXd& y, const Eigen::VectorXd& weights,
               Eigen::Ref<Eigen::MatrixXd> hess) const override;

 private:
  int n_;
  BipedDynamics dynamics_;  // on an SSP point of the nominal model
  Eigen::MatrixXd map_;     // L: the point (theta, dtheta, ddtheta, tau) = L y
};

/// The law at every point p of a variant's single support, point p of the reference at the
/// same time (same mesh, shared duration): n rows per point, point-major.
class ComputedTorqueLaw : public ConstraintSet {
 public:
  /// @throws std::invalid_argument when the two phases do not share a mesh
  ComputedTorqueLaw(std::string name, const Phase& variant, const Phase& reference,
                    const dynamics::Model& nominal, const FeedbackGains& gains);
  void values(const Eigen::VectorXd& x, Eigen::Ref<Eigen::VectorXd> g) const override;
  void jacobian(const Eigen::VectorXd& x, Triplets& out) const override;
  void hessian(const Eigen::VectorXd& x, const Eigen::VectorXd& lambda,
               Triplets& out) const override;
  GridNode nodeOf(int row) const override {
    return {"point", row / residual_.rows(), row % residual_.rows()};
  }

 private:
  ComputedTorqueResidual residual_;
  PointPattern pattern_;                   // of the residual in y
  std::vector<std::vector<int>> indices_;  // per point: the NLP variables of y
};

}  // namespace gaitopt::ocp
