#pragma once
/// @file point_function.hpp
/// Functions of one collocation point's variables v = [x, xdot, u, z] with exact dense
/// derivatives, and the two ways a phase uses them: as a path constraint at every point
/// (dynamics, friction cones, ...) and as the integrand of a running cost (quadrature).
#include <memory>
#include <utility>
#include <vector>

#include "ocp/transcription/collocation.hpp"

namespace gaitopt::ocp {

class PointFunction {
 public:
  virtual ~PointFunction() = default;
  virtual int rows() const = 0;
  /// f(v), rows() values.
  virtual void evaluate(const Eigen::VectorXd& v, Eigen::Ref<Eigen::VectorXd> f) const = 0;
  /// df/dv, rows() x v.size(), dense.
  virtual void jacobian(const Eigen::VectorXd& v, Eigen::Ref<Eigen::MatrixXd> jac) const = 0;
  /// sum_i weights_i d2 f_i / dv2, v.size() x v.size(), symmetric.
  virtual void hessian(const Eigen::VectorXd& v, const Eigen::VectorXd& weights,
                       Eigen::Ref<Eigen::MatrixXd> hess) const = 0;
  virtual Eigen::VectorXd lowerBounds() const { return Eigen::VectorXd::Zero(rows()); }
  virtual Eigen::VectorXd upperBounds() const { return Eigen::VectorXd::Zero(rows()); }
};

/// Structural nonzeros of a point function: the union of the nonzero entries of its Jacobian
/// and Hessian at three seeded random points in [-1, 1]^size. Exact for the smooth functions
/// used here (trigonometric polynomials), whose entries vanish only on measure-zero sets.
struct PointPattern {
  std::vector<std::pair<int, int>> jacobian;  ///< (row, col)
  std::vector<std::pair<int, int>> hessian;   ///< (row, col), row >= col
};
PointPattern probePattern(const PointFunction& f, int size);

/// f(v_p) within bounds at every point of a phase. Each point fills its own block, with the
/// entries of the probed pattern only (fewer nonzeros for Ipopt's linear solver).
class PathConstraint : public ConstraintSet {
 public:
  /// @param phase  the phase the layout's points belong to (ConstraintSet)
  PathConstraint(std::string name, std::string phase, const PhaseLayout& layout,
                 std::shared_ptr<const PointFunction> function);
  Eigen::VectorXd lowerBounds() const override;
  Eigen::VectorXd upperBounds() const override;
  void values(const Eigen::VectorXd& x, Eigen::Ref<Eigen::VectorXd> g) const override;
  void jacobian(const Eigen::VectorXd& x, Triplets& out) const override;
  void hessian(const Eigen::VectorXd& x, const Eigen::VectorXd& lambda,
               Triplets& out) const override;
  /// Row r is row r % function->rows() of collocation point r / function->rows().
  GridNode nodeOf(int row) const override { return {"point", row / f_->rows(), row % f_->rows()}; }

 private:
  PhaseLayout layout_;
  std::shared_ptr<const PointFunction> f_;
  PointPattern pattern_;
};

/// The running cost T sum_p w_p L(v_p), with the phase's quadrature weights for unit
/// duration; L has one row. A free T is differentiated too.
class QuadratureCost : public CostTerm {
 public:
  /// @param weights  per point, for T = 1; empty: the scheme's own (quadratureWeights)
  QuadratureCost(std::string name, const PhaseLayout& layout,
                 std::shared_ptr<const PointFunction> integrand, Eigen::VectorXd weights = {});
  double value(const Eigen::VectorXd& x) const override;
  void gradient(const Eigen::VectorXd& x, Eigen::Ref<Eigen::VectorXd> grad) const override;
  void hessian(const Eigen::VectorXd& x, double factor, Triplets& out) const override;

 private:
  double unitDurationValue(const Eigen::VectorXd& x) const;  ///< sum_p w_p L(v_p)

  PhaseLayout layout_;
  std::shared_ptr<const PointFunction> f_;
  Eigen::VectorXd weights_;
  PointPattern pattern_;
};

/// Appends the pattern's entries of a symmetric block whose first row/column is variable
/// `offset` (zeros included: the sparsity contract of nlp.hpp).
void appendPattern(const Eigen::MatrixXd& block, const std::vector<std::pair<int, int>>& entries,
                   int offset, Triplets& out);

}  // namespace gaitopt::ocp
