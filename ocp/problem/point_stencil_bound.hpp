#pragma once
/// @file point_stencil_bound.hpp
/// Two-sided bounds on linear combinations of one block of one phase's points (the accelerations
/// a or the torques u), per entry: for each stencil s (points p_i, weights w_i, allowance c) and
/// entry j,
///   -c J T <= sum_i w_i b_j(p_i) <= c J T,
/// as the two rows sum - c J T <= 0 and sum + c J T >= 0. Both rows are linear in the block and
/// in the phase's duration T when it is free, so the set's Jacobian is constant and its Hessian
/// empty. The bounds on how fast accelerations change (jerk_limit.hpp), on how much the jerk
/// jumps at a node (jerk_jump.hpp) and on how fast torques change (torque_rate_limit.hpp) are
/// such stencils.
#include <string>
#include <vector>

#include "ocp/transcription/nlp.hpp"
#include "ocp/transcription/phase.hpp"

namespace gaitopt::ocp {

struct PointStencil {
  std::vector<int> points;
  std::vector<double> weights;
  double allowance = 1;  ///< c: the bound is c J T
};

/// The stencils {b_p, b_{p+1}} with weights (-1, 1) and allowance t_{p+1} - t_p per unit T: a
/// bound on the block's rate of change between consecutive points.
std::vector<PointStencil> consecutivePointStencils(const PhaseLayout& layout);

class PointStencilBound : public ConstraintSet {
 public:
  /// @param bound  J, in the stencils' units
  /// @param block  the block of each point the stencils combine
  PointStencilBound(std::string name, const Phase& phase, double bound,
                    std::vector<PointStencil> stencils, Slice PointLayout::*block);
  Eigen::VectorXd lowerBounds() const override;
  Eigen::VectorXd upperBounds() const override;
  void values(const Eigen::VectorXd& x, Eigen::Ref<Eigen::VectorXd> g) const override;
  void jacobian(const Eigen::VectorXd& x, Triplets& out) const override;
  void hessian(const Eigen::VectorXd&, const Eigen::VectorXd&, Triplets&) const override {}

 protected:
  /// Rows 2 n s .. 2 n (s + 1) - 1 belong to stencil s: row 2 j of them is entry j's upper row,
  /// 2 j + 1 its lower one.
  int stencilOf(int row) const { return row / (2 * block_.size); }
  int entryOf(int row) const { return row % (2 * block_.size); }
  const PointStencil& stencil(int s) const { return stencils_[static_cast<size_t>(s)]; }

 private:
  Phase phase_;
  Slice block_;
  double bound_;
  std::vector<PointStencil> stencils_;
};

}  // namespace gaitopt::ocp
