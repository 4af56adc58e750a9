#pragma once
/// @file point_function.hpp
/// Functions of one collocation point's variables v = [x, xdot, u, z] with exact dense
/// derivatives, and the two ways a phase uses them: as a path constraint at every point
/// (dynamics, friction cones, ...) and as the integrand of a running cost (quadrature).
#include <memory>

#include "ocp/collocation.hpp"

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

/// f(v_p) within bounds at every point of a phase. Each point fills its own dense block.
class PathConstraint : public ConstraintSet {
 public:
  PathConstraint(std::string name, const PhaseLayout& layout,
                 std::shared_ptr<const PointFunction> function);
  Eigen::VectorXd lowerBounds() const override;
  Eigen::VectorXd upperBounds() const override;
  void values(const Eigen::VectorXd& x, Eigen::Ref<Eigen::VectorXd> g) const override;
  void jacobian(const Eigen::VectorXd& x, Triplets& out) const override;
  void hessian(const Eigen::VectorXd& x, const Eigen::VectorXd& lambda,
               Triplets& out) const override;

 private:
  PhaseLayout layout_;
  std::shared_ptr<const PointFunction> f_;
};

/// The running cost sum_p w_p L(v_p), with the phase's quadrature weights; L has one row.
class QuadratureCost : public CostTerm {
 public:
  QuadratureCost(std::string name, const PhaseLayout& layout,
                 std::shared_ptr<const PointFunction> integrand);
  double value(const Eigen::VectorXd& x) const override;
  void gradient(const Eigen::VectorXd& x, Eigen::Ref<Eigen::VectorXd> grad) const override;
  void hessian(const Eigen::VectorXd& x, double factor, Triplets& out) const override;

 private:
  PhaseLayout layout_;
  std::shared_ptr<const PointFunction> f_;
  Eigen::VectorXd weights_;
};

/// Appends the lower triangle of a dense symmetric block whose first row/column is variable
/// `offset` (every entry, zeros included: the sparsity contract of nlp.hpp).
void appendLowerTriangle(const Eigen::MatrixXd& block, int offset, Triplets& out);

}  // namespace gaitopt::ocp
