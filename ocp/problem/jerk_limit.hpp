#pragma once
/// @file jerk_limit.hpp
/// A bound on how fast every link's angular acceleration changes between consecutive
/// collocation points (config constraints.jerk_limit J [rad/s^3]):
///   -J <= (ddtheta_{p+1} - ddtheta_p) / (t_{p+1} - t_p) <= J,
/// written as two rows free of divisions, a_{p+1} - a_p - J dt_p T <= 0 and
/// a_{p+1} - a_p + J dt_p T >= 0 (dt_p the points' spacing per unit duration T), linear also when
/// T is free. Hermite-Simpson's acceleration is quadratic on a segment, so its slope at the
/// segment's ends is at most twice the bound on the half-segments: |theta'''| <= 2 J.
/// Why: the export's rates are the exact derivatives of its angles, but a check by differences
/// of 1 kHz samples carries the truncation error h^2/6 |theta'''| <= h^2 J / 3; the least
/// cost-of-transport gait's swing shank had |theta'''| near 10^5 rad/s^3 before touchdown, a
/// 0.3 % error of the peak rate.
#include <string>

#include "ocp/transcription/nlp.hpp"
#include "ocp/transcription/phase.hpp"

namespace gaitopt::ocp {

class JerkLimit : public ConstraintSet {
 public:
  JerkLimit(std::string name, const Phase& phase, double jerk);
  Eigen::VectorXd lowerBounds() const override;
  Eigen::VectorXd upperBounds() const override;
  void values(const Eigen::VectorXd& x, Eigen::Ref<Eigen::VectorXd> g) const override;
  void jacobian(const Eigen::VectorXd& x, Triplets& out) const override;
  void hessian(const Eigen::VectorXd&, const Eigen::VectorXd&, Triplets&) const override {}
  /// Rows 2 n p .. 2 n (p + 1) - 1 bound the change from point p to point p + 1.
  GridNode nodeOf(int row) const override {
    return {"point", row / (2 * phase_.point.n), row % (2 * phase_.point.n)};
  }

 private:
  /// Spacing of points p and p + 1 per unit duration.
  double spacing(int p) const {
    return phase_.layout.time(p + 1, 1.0) - phase_.layout.time(p, 1.0);
  }

  Phase phase_;
  double jerk_;
};

}  // namespace gaitopt::ocp
