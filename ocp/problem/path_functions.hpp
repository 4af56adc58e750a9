#pragma once
/// @file path_functions.hpp
/// Running costs and kinematic path constraints of the gait, as point functions of a collocation
/// point v laid out by PointLayout (point_layout.hpp).
#include "dynamics/model.hpp"
#include "ocp/problem/clearance_profile.hpp"
#include "ocp/transcription/phase.hpp"
#include "ocp/transcription/point_function.hpp"

namespace gaitopt::ocp {

/// L = weight * sum_j tau_j^2 (Kelly 2017's cost; a small weight regularises abs_work) [N^2 m^2].
class TorqueSquared : public PointFunction {
 public:
  explicit TorqueSquared(const PointLayout& point, double weight = 1.0)
      : point_(point), weight_(weight) {}
  int rows() const override { return 1; }
  void evaluate(const Eigen::VectorXd& v, Eigen::Ref<Eigen::VectorXd> f) const override;
  void jacobian(const Eigen::VectorXd& v, Eigen::Ref<Eigen::MatrixXd> jac) const override;
  void hessian(const Eigen::VectorXd& v, const Eigen::VectorXd& w,
               Eigen::Ref<Eigen::MatrixXd> hess) const override;

 private:
  PointLayout point_;
  double weight_;
};

/// Absolute mechanical work made smooth with slack variables
/// (docs/design.md#the-optimal-control-problem): each joint's power tau_j dq_j = s+_j - s-_j with
/// s+, s- >= 0 (WorkSplit), and the running cost L = weight sum_j (s+_j + s-_j), which equals
/// weight sum_j |tau_j dq_j| at the optimum.
class AbsoluteWork : public PointFunction {
 public:
  AbsoluteWork(const PointLayout& point, double weight = 1.0) : point_(point), weight_(weight) {}
  int rows() const override { return 1; }
  void evaluate(const Eigen::VectorXd& v, Eigen::Ref<Eigen::VectorXd> f) const override {
    f(0) = weight_ * (point_.work_plus.of(v).sum() + point_.work_minus.of(v).sum());
  }
  void jacobian(const Eigen::VectorXd&, Eigen::Ref<Eigen::MatrixXd> jac) const override {
    jac.setZero();
    point_.work_plus.of(jac.row(0)).setConstant(weight_);
    point_.work_minus.of(jac.row(0)).setConstant(weight_);
  }
  void hessian(const Eigen::VectorXd&, const Eigen::VectorXd&,
               Eigen::Ref<Eigen::MatrixXd> hess) const override {
    hess.setZero();
  }

 private:
  PointLayout point_;
  double weight_;
};

/// tau_j dq_j - s+_j + s-_j = 0 with dq = M dtheta (Mu 2.41): joint power split into its
/// positive and negative parts.
class WorkSplit : public PointFunction {
 public:
  explicit WorkSplit(const PointLayout& point) : point_(point) {}
  int rows() const override { return point_.n; }
  void evaluate(const Eigen::VectorXd& v, Eigen::Ref<Eigen::VectorXd> f) const override;
  void jacobian(const Eigen::VectorXd& v, Eigen::Ref<Eigen::MatrixXd> jac) const override;
  void hessian(const Eigen::VectorXd& v, const Eigen::VectorXd& w,
               Eigen::Ref<Eigen::MatrixXd> hess) const override;

 private:
  PointLayout point_;
};

/// Knees never hyperextend: stance knee q1 = theta_1 - theta_2 >= 0 and swing knee
/// q_{n-1} = theta_{n-1} - theta_n <= 0 (knee forward in both legs, conventions.hpp); they
/// flex at most max_stance / max_swing [rad] (an upright gait; kInf: unbounded), and the stance
/// knee at least min_stance (the double support's trailing knee kept off its singular straight
/// pose, ocp_config.hpp's min_trailing_knee_flexion).
class KneeDirection : public PointFunction {
 public:
  explicit KneeDirection(const PointLayout& point, double max_stance = kInf,
                         double max_swing = kInf, double min_stance = 0)
      : point_(point), max_stance_(max_stance), max_swing_(max_swing), min_stance_(min_stance) {}
  int rows() const override { return 2; }
  void evaluate(const Eigen::VectorXd& v, Eigen::Ref<Eigen::VectorXd> f) const override;
  void jacobian(const Eigen::VectorXd& v, Eigen::Ref<Eigen::MatrixXd> jac) const override;
  void hessian(const Eigen::VectorXd&, const Eigen::VectorXd&,
               Eigen::Ref<Eigen::MatrixXd> hess) const override {
    hess.setZero();
  }
  Eigen::VectorXd lowerBounds() const override;
  Eigen::VectorXd upperBounds() const override;

 private:
  PointLayout point_;
  double max_stance_, max_swing_, min_stance_;
};

/// Physical joint rates dq = M dtheta (Mu 2.39-2.41: dq_0 = dtheta_0, dq_j = dtheta_{j-1} -
/// dtheta_j) within the robot file's joint velocity limits, |dq_j| <= velocity_limit_j [rad/s].
class JointRateLimits : public PointFunction {
 public:
  JointRateLimits(const dynamics::Model& model, const PointLayout& point);
  int rows() const override { return point_.n; }
  void evaluate(const Eigen::VectorXd& v, Eigen::Ref<Eigen::VectorXd> f) const override;
  void jacobian(const Eigen::VectorXd& v, Eigen::Ref<Eigen::MatrixXd> jac) const override;
  void hessian(const Eigen::VectorXd&, const Eigen::VectorXd&,
               Eigen::Ref<Eigen::MatrixXd> hess) const override {
    hess.setZero();
  }
  Eigen::VectorXd lowerBounds() const override { return -limit_; }
  Eigen::VectorXd upperBounds() const override { return limit_; }

 private:
  PointLayout point_;
  Eigen::VectorXd limit_;  ///< per joint [rad/s]
};

/// Swing-tip height above the ground, y_E = sum_j a_j l_j cos(theta_j) (Mu 2.1) [m]; never
/// below it.
class SwingHeight : public PointFunction {
 public:
  SwingHeight(const dynamics::Model& model, const PointLayout& point)
      : model_(&model), point_(point) {}
  int rows() const override { return 1; }
  void evaluate(const Eigen::VectorXd& v, Eigen::Ref<Eigen::VectorXd> f) const override;
  void jacobian(const Eigen::VectorXd& v, Eigen::Ref<Eigen::MatrixXd> jac) const override;
  void hessian(const Eigen::VectorXd& v, const Eigen::VectorXd& w,
               Eigen::Ref<Eigen::MatrixXd> hess) const override;
  Eigen::VectorXd lowerBounds() const override { return Eigen::VectorXd::Zero(1); }
  Eigen::VectorXd upperBounds() const override { return Eigen::VectorXd::Constant(1, kInf); }

 private:
  const dynamics::Model* model_;
  PointLayout point_;
};

/// y_E(v_p) >= h(s_p) at every point p of the single support, s_p = t_p / T its phase fraction
/// (clearance_profile.hpp). The points sit at fixed fractions of T, so each bound is a constant
/// even when T is free: the rows and their derivatives are those of SwingHeight.
class SwingClearance : public PathConstraint {
 public:
  SwingClearance(const dynamics::Model& model, const Phase& phase, const ClearanceProfile& profile);
  Eigen::VectorXd lowerBounds() const override { return lower_; }

 private:
  Eigen::VectorXd lower_;  ///< h(s_p) per point [m]
};

}  // namespace gaitopt::ocp
