#pragma once
/// @file variant_sets.hpp
/// The constraint sets that tie a model variant to the nominal (gait_shape.hpp): its torques
/// given by the feedback law around the nominal reference at every collocation point, and its
/// end state near the nominal's. Both have exact derivatives: the law is linear, the distance
/// a sum of squares.
#include <vector>

#include "dynamics/model.hpp"
#include "ocp/shape/shape_config.hpp"
#include "ocp/transcription/nlp.hpp"
#include "ocp/transcription/phase.hpp"

namespace gaitopt::ocp {

/// u_k = u_ref + kp M (theta_ref - theta_k) + kd M (dtheta_ref - dtheta_k) on every actuated
/// joint at every point p, M the joint map of Mu (2.41) (q = M theta), so the law acts on joint
/// angles as a joint PD does; point p of the variant and of the reference sit at the same time
/// (same mesh, shared duration). Rows: u_k - (the law) = 0, point-major. An unactuated joint
/// has no row: both torques are held at zero by their bounds.
class FeedbackLaw : public ConstraintSet {
 public:
  /// @throws std::invalid_argument when the two phases do not share a mesh
  FeedbackLaw(std::string name, const Phase& variant, const Phase& reference,
              const dynamics::Model& model, const FeedbackGains& gains);
  void values(const Eigen::VectorXd& x, Eigen::Ref<Eigen::VectorXd> g) const override;
  void jacobian(const Eigen::VectorXd& x, Triplets& out) const override;
  void hessian(const Eigen::VectorXd&, const Eigen::VectorXd&, Triplets&) const override {}
  GridNode nodeOf(int row) const override { return {"point", row / joints_, row % joints_}; }

 private:
  Triplets entries_;  // the constant Jacobian: g = A x
  int joints_;        // rows per point
};

/// One row, |x[a] - x[b]|^2 <= tolerance^2: two states within a Euclidean distance. Relabelling
/// (Mu 2.38) permutes a state's entries and adds the same constant to both, so the distance
/// after relabelling is the distance before it; the ends are compared as they are.
class StateDistance : public ConstraintSet {
 public:
  StateDistance(std::string name, std::vector<int> a, std::vector<int> b, double tolerance);
  Eigen::VectorXd lowerBounds() const override { return Eigen::VectorXd::Constant(1, -kInf); }
  Eigen::VectorXd upperBounds() const override {
    return Eigen::VectorXd::Constant(1, tolerance_ * tolerance_);
  }
  void values(const Eigen::VectorXd& x, Eigen::Ref<Eigen::VectorXd> g) const override;
  void jacobian(const Eigen::VectorXd& x, Triplets& out) const override;
  void hessian(const Eigen::VectorXd& x, const Eigen::VectorXd& lambda,
               Triplets& out) const override;

 private:
  std::vector<int> a_, b_;
  double tolerance_;
};

}  // namespace gaitopt::ocp
