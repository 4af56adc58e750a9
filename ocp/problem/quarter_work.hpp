#pragma once
/// @file quarter_work.hpp
/// Absolute work that holds between the collocation points. In Hermite-Simpson the
/// torque u and the rate v are quadratics through a segment's three points, so each joint's
/// power tau_j dq_j is a quartic in time. Work slacks at the three points alone let the optimum
/// put tau_j = 0 or dq_j = 0 at each of them and work freely in between: the least-cost-of-
/// transport gait spent 1.34 J per step at its points and 5.48 J along its 1 kHz export. Two
/// more splits per segment, at a quarter and three quarters of it, leave no nonzero quartic that
/// vanishes at all five places, and the work is the five-point composite Simpson rule
/// h/12 (1, 4, 2, 4, 1) over them (the points' share: fivePointWeights).
#include "ocp/transcription/nlp.hpp"
#include "ocp/transcription/phase.hpp"

namespace gaitopt::ocp {

/// The split slacks of one phase's quarter points: per segment k and quarter r (0: s = 1/4,
/// 1: s = 3/4), s+ (n) then s- (n), all >= 0.
struct QuarterSlacks {
  int offset = 0;  ///< first variable in the decision vector
  int segments = 0;
  int n = 0;
  int size() const { return segments * 2 * 2 * n; }
  int plus(int k, int r, int j) const { return offset + (k * 2 + r) * 2 * n + j; }
  int minus(int k, int r, int j) const { return plus(k, r, j) + n; }
};

/// tau_j(s) dq_j(s) - s+_j + s-_j = 0 at s = 1/4 and 3/4 of every segment, with tau and
/// dtheta the Lagrange quadratics through the segment's points and dq = M dtheta (Mu 2.41).
class QuarterWorkSplit : public ConstraintSet {
 public:
  QuarterWorkSplit(std::string name, const Phase& phase, const QuarterSlacks& slacks);
  void values(const Eigen::VectorXd& x, Eigen::Ref<Eigen::VectorXd> g) const override;
  void jacobian(const Eigen::VectorXd& x, Triplets& out) const override;
  void hessian(const Eigen::VectorXd& x, const Eigen::VectorXd& lambda,
               Triplets& out) const override;
  /// n rows per quarter point, two quarter points per segment.
  GridNode nodeOf(int row) const override {
    return {"segment", row / (2 * slacks_.n), row % (2 * slacks_.n)};
  }

 private:
  Phase phase_;
  QuarterSlacks slacks_;
};

/// weight T sum_k (h_k / T) (4 / 12) sum_{r, j} (s+ + s-): the quarter points' share of the
/// five-point rule, with a free T a factor of its own.
class QuarterWorkCost : public CostTerm {
 public:
  QuarterWorkCost(std::string name, const PhaseLayout& layout, const QuarterSlacks& slacks,
                  double weight);
  double value(const Eigen::VectorXd& x) const override;
  void gradient(const Eigen::VectorXd& x, Eigen::Ref<Eigen::VectorXd> grad) const override;
  void hessian(const Eigen::VectorXd& x, double factor, Triplets& out) const override;

 private:
  double coefficient(int k) const;  ///< weight (h_k / T) 4 / 12
  PhaseLayout layout_;
  QuarterSlacks slacks_;
  double weight_;
};

/// The collocation points' weights in the five-point rule, for T = 1: h/12 at each end of a
/// segment and 2 h/12 at its midpoint (Hermite-Simpson layouts only).
Eigen::VectorXd fivePointWeights(const PhaseLayout& layout);

/// Adds the phase's quarter slacks (started from the split of the initial guess's power), their
/// split constraints and their cost `weight`; returns the slacks.
QuarterSlacks addQuarterWork(Nlp& nlp, const Phase& phase, double weight);

}  // namespace gaitopt::ocp
