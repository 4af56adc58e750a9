#pragma once
/// @file variant_sets.hpp
/// The constraint sets that tie a model variant to the nominal (gait_shape.hpp): its torques
/// given by the feedback law around the nominal reference at every collocation point, and its
/// end state near the nominal's, and the optional cost of its spread about the reference. All
/// have exact derivatives: the law is linear, the distance and the spread sums of squares.
#include <vector>

#include "dynamics/model.hpp"
#include "ocp/shape/shape_config.hpp"
#include "ocp/transcription/collocation.hpp"
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

/// weight T sum_p w_p |theta_k(p) - theta_ref(p)|^2 [rad^2 s]: the spread of a variant's link
/// angles about the reference's over one phase, by the phase's quadrature (w_p for T = 1, T its
/// duration, a variable when free). An optional term beside the nominal's cost: it pays for
/// the variants staying close to the reference, not only ending near it.
class VariantSpread : public CostTerm {
 public:
  VariantSpread(std::string name, const Phase& variant, const Phase& reference, double weight);
  double value(const Eigen::VectorXd& x) const override;
  void gradient(const Eigen::VectorXd& x, Eigen::Ref<Eigen::VectorXd> grad) const override;
  void hessian(const Eigen::VectorXd& x, double factor, Triplets& out) const override;

 private:
  struct Pair {
    int a, b;  // the variant's and the reference's angle
    double w;  // the point's quadrature weight times the cost weight
  };
  double duration(const Eigen::VectorXd& x) const { return layout_.durationAt(x); }
  std::vector<Pair> pairs_;
  PhaseLayout layout_;  // the variant's: its duration is the reference's
};

}  // namespace gaitopt::ocp
