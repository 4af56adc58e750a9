#pragma once
/// @file interior_work.hpp
/// Absolute work that holds between the collocation points. In Hermite-Simpson a segment's
/// torque u is the quadratic through its three points and its rate v the cubic whose derivative
/// is the quadratic through their accelerations (collocation_interpolation.hpp, what the export
/// and a controller receive), so each joint's power tau_j dq_j is a quintic in time. Work
/// slacks at the three points alone let the optimum put tau_j = 0 or dq_j = 0 at each of them
/// and work freely in between: the least-cost-of-transport gait spent 1.34 J per step at its
/// points and 5.48 J along its 1 kHz export. The power is therefore also split at the interior
/// ends of kWorkSubIntervals equal sub-intervals of every segment, and the work is the composite
/// Simpson rule over them. Both choices are measured in
/// docs/optimal_gaits.md#absolute-work-between-the-points: with the rate read as the quadratic
/// through the points' rates instead of the export's cubic, the optimum hid 29 % of its work
/// where the two differ; with 4 sub-intervals instead of 8, 5-13 % on the absolute-work problem.
#include "ocp/transcription/nlp.hpp"
#include "ocp/transcription/phase.hpp"

namespace gaitopt::ocp {

/// Equal Simpson sub-intervals per segment over which the absolute work is split and
/// integrated (even).
inline constexpr int kWorkSubIntervals = 8;

/// Composite Simpson weight, in units of h, of sub-interval end i (0 .. kWorkSubIntervals): 1 at
/// the segment's ends, 4 at odd ends and 2 at even ones, over 3 kWorkSubIntervals.
constexpr double simpsonWeight(int i) {
  const double w = i == 0 || i == kWorkSubIntervals ? 1.0 : (i % 2 == 1 ? 4.0 : 2.0);
  return w / (3.0 * kWorkSubIntervals);
}

/// The split slacks of one phase: per segment k and sample r (the sub-interval ends inside the
/// segment but its midpoint, in time order), s+ (n) then s- (n), all >= 0.
struct InteriorSlacks {
  int offset = 0;  ///< first variable in the decision vector
  int segments = 0;
  int n = 0;
  int samples() const { return kWorkSubIntervals - 2; }
  /// Local time s in (0, 1) of sample r.
  double at(int r) const { return static_cast<double>(end(r)) / kWorkSubIntervals; }
  /// Composite Simpson weight of sample r in units of h.
  double weight(int r) const { return simpsonWeight(end(r)); }
  /// The sub-interval end (1 .. kWorkSubIntervals - 1, the midpoint skipped) of sample r.
  int end(int r) const { return r + 1 < kWorkSubIntervals / 2 ? r + 1 : r + 2; }
  int size() const { return segments * samples() * 2 * n; }
  int plus(int k, int r, int j) const { return offset + (k * samples() + r) * 2 * n + j; }
  int minus(int k, int r, int j) const { return plus(k, r, j) + n; }
};

/// tau_j(s) dq_j(s) - s+_j + s-_j = 0 at every sample s of every segment, with tau the quadratic
/// through the segment's points, dtheta the export's cubic and dq = M dtheta (Mu 2.41); with a
/// free T the cubic's h = T (s_{k+1} - s_k) makes each row trilinear in (u, T, a).
class InteriorWorkSplit : public ConstraintSet {
 public:
  InteriorWorkSplit(std::string name, const Phase& phase, const InteriorSlacks& slacks);
  void values(const Eigen::VectorXd& x, Eigen::Ref<Eigen::VectorXd> g) const override;
  void jacobian(const Eigen::VectorXd& x, Triplets& out) const override;
  void hessian(const Eigen::VectorXd& x, const Eigen::VectorXd& lambda,
               Triplets& out) const override;
  /// n rows per sample, samples() samples per segment.
  GridNode nodeOf(int row) const override {
    return {"segment", row / (slacks_.samples() * slacks_.n),
            row % (slacks_.samples() * slacks_.n)};
  }

 private:
  Phase phase_;
  InteriorSlacks slacks_;
};

/// weight T sum_k (h_k / T) sum_r w_r sum_j (s+ + s-): the samples' share of the composite
/// Simpson rule, with a free T a factor of its own.
class InteriorWorkCost : public CostTerm {
 public:
  InteriorWorkCost(std::string name, const PhaseLayout& layout, const InteriorSlacks& slacks,
                   double weight);
  double value(const Eigen::VectorXd& x) const override;
  void gradient(const Eigen::VectorXd& x, Eigen::Ref<Eigen::VectorXd> grad) const override;
  void hessian(const Eigen::VectorXd& x, double factor, Triplets& out) const override;

 private:
  double coefficient(int k, int r) const;  ///< weight (h_k / T) times sample r's weight
  PhaseLayout layout_;
  InteriorSlacks slacks_;
  double weight_;
};

/// The collocation points' share of the composite Simpson rule, for T = 1: h / (3 m) at each
/// end of a segment of m sub-intervals and 2 or 4 times that at its midpoint (Hermite-Simpson
/// layouts only).
Eigen::VectorXd pointWeights(const PhaseLayout& layout);

/// Adds the phase's slacks (started from the split of the initial guess's power), their
/// split constraints and their cost `weight`; returns the slacks.
InteriorSlacks addInteriorWork(Nlp& nlp, const Phase& phase, double weight);

}  // namespace gaitopt::ocp
