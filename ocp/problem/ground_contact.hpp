#pragma once
/// @file ground_contact.hpp
/// Contact conditions at a collocation point v (point_layout.hpp;
/// docs/design.md#the-optimal-control-problem); every row is
/// >= 0 when its condition holds:
///   F_By - F_min, mu F_By - F_Bx, mu F_By + F_Bx         (unilateral, Coulomb friction at B)
///   F_Ey - F_min, mu F_Ey - F_Ex, mu F_Ey + F_Ex         (the same at E, DSP only)
///   M + heel Fy, hi Fy - M                                (ZMP in [-heel, hi], if enabled)
///   heel F_By - tau0, toe F_By + tau0                     (foot B's own CoP -tau0 / F_By in
///                                                          [-heel, toe], DSP with the ZMP)
/// where F_min >= 0 is the least normal force a loaded tip keeps (a margin against lift-off:
/// a tip loaded with 0 N at a point leaves the ground at the least tracking error), heel and toe
/// are those of the foot the ZMP is kept on (the robot's less any margin, ocp_config.hpp
/// marginFoot), and F_B = m (a_com + g e_y) - F_E from total linear momentum (ground.hpp), F_E =
/// lambda, M = x_zmp Fy = step_length F_Ey - tau0 (moment of the ground wrench about B, ground
/// moment -tau0), Fy = F_By + F_Ey, hi = toe (SSP) or step_length + toe (DSP). Every row is linear
/// in s = (F_B, F_E, tau0); F_B is the only nonlinear part, so the derivatives are those of a_com
/// (point_acceleration_derivatives.hpp), exact and cheap.
#include <optional>

#include "dynamics/model.hpp"
#include "ocp/transcription/point_function.hpp"
#include "ocp/transcription/point_layout.hpp"

namespace gaitopt::ocp {

class GroundContact : public PointFunction {
 public:
  /// `point`: the point's layout; with a contact force (double support) both tips carry cones.
  /// `zmp_foot`: the foot the ZMP and CoP rows keep them on; none: no ZMP rows.
  /// `mu`: the friction coefficient the cones use (the robot's, less any margin).
  /// `min_normal`: F_min [N], the least normal force on every tip in contact.
  GroundContact(const dynamics::Model& model, const PointLayout& point,
                const std::optional<dynamics::Foot>& zmp_foot, double step_length, double mu,
                double min_normal = 0);
  int rows() const override { return static_cast<int>(rows_.rows()); }
  void evaluate(const Eigen::VectorXd& v, Eigen::Ref<Eigen::VectorXd> f) const override;
  void jacobian(const Eigen::VectorXd& v, Eigen::Ref<Eigen::MatrixXd> jac) const override;
  void hessian(const Eigen::VectorXd& v, const Eigen::VectorXd& w,
               Eigen::Ref<Eigen::MatrixXd> hess) const override;
  Eigen::VectorXd lowerBounds() const override { return lower_; }
  Eigen::VectorXd upperBounds() const override { return Eigen::VectorXd::Constant(rows(), kInf); }

 private:
  /// s = (F_Bx, F_By, F_Ex, F_Ey, tau0) at the point.
  Eigen::Matrix<double, 5, 1> contactQuantities(const Eigen::VectorXd& v) const;

  const dynamics::Model* model_;
  PointLayout point_;
  Eigen::Matrix<double, Eigen::Dynamic, 5> rows_;  // g = rows_ * s
  Eigen::VectorXd lower_;                          // 0, or F_min on the normal-force rows
};

}  // namespace gaitopt::ocp
