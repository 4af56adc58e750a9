#pragma once
/// @file acceleration_stencil_bound.hpp
/// Two-sided bounds on linear combinations of one phase's accelerations, per link: for each
/// stencil s (points p_i, weights w_i, allowance c) and link j,
///   -c J T <= sum_i w_i a_j(p_i) <= c J T,
/// as the two rows sum - c J T <= 0 and sum + c J T >= 0. Both rows are linear in the
/// accelerations and in the phase's duration T when it is free, so the set's Jacobian is constant
/// and its Hessian empty. The bounds on how fast accelerations change (jerk_limit.hpp) and on how
/// much the jerk jumps at a node (jerk_jump.hpp) are such stencils.
#include <string>
#include <vector>

#include "ocp/transcription/nlp.hpp"
#include "ocp/transcription/phase.hpp"

namespace gaitopt::ocp {

struct AccelerationStencil {
  std::vector<int> points;
  std::vector<double> weights;
  double allowance = 1;  ///< c: the bound is c J T
};

class AccelerationStencilBound : public ConstraintSet {
 public:
  /// @param bound  J, in the stencils' units
  AccelerationStencilBound(std::string name, const Phase& phase, double bound,
                           std::vector<AccelerationStencil> stencils);
  Eigen::VectorXd lowerBounds() const override;
  Eigen::VectorXd upperBounds() const override;
  void values(const Eigen::VectorXd& x, Eigen::Ref<Eigen::VectorXd> g) const override;
  void jacobian(const Eigen::VectorXd& x, Triplets& out) const override;
  void hessian(const Eigen::VectorXd&, const Eigen::VectorXd&, Triplets&) const override {}

 protected:
  /// Rows 2 n s .. 2 n (s + 1) - 1 belong to stencil s: row 2 j of them is link j's upper row,
  /// 2 j + 1 its lower one.
  int stencilOf(int row) const { return row / (2 * phase_.point.n); }
  int entryOf(int row) const { return row % (2 * phase_.point.n); }
  const AccelerationStencil& stencil(int s) const { return stencils_[static_cast<size_t>(s)]; }

 private:
  Phase phase_;
  double bound_;
  std::vector<AccelerationStencil> stencils_;
};

}  // namespace gaitopt::ocp
