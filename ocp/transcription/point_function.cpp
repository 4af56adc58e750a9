#include "ocp/transcription/point_function.hpp"

#include <algorithm>
#include <cstdlib>
#include <stdexcept>

namespace gaitopt::ocp {

void appendPattern(const Eigen::MatrixXd& block, const std::vector<std::pair<int, int>>& entries,
                   int offset, Triplets& out) {
  for (const auto& [r, c] : entries) out.emplace_back(offset + r, offset + c, block(r, c));
}

PointPattern probePattern(const PointFunction& f, int size) {
  std::srand(7);  // Eigen's Random uses std::rand: seeded for a reproducible pattern
  Eigen::Matrix<bool, Eigen::Dynamic, Eigen::Dynamic> jac_nz =
      Eigen::Matrix<bool, Eigen::Dynamic, Eigen::Dynamic>::Constant(f.rows(), size, false);
  Eigen::Matrix<bool, Eigen::Dynamic, Eigen::Dynamic> hess_nz =
      Eigen::Matrix<bool, Eigen::Dynamic, Eigen::Dynamic>::Constant(size, size, false);
  Eigen::MatrixXd jac(f.rows(), size), hess(size, size);
  for (int trial = 0; trial < 3; ++trial) {
    const Eigen::VectorXd v = Eigen::VectorXd::Random(size);
    f.jacobian(v, jac);
    f.hessian(v, Eigen::VectorXd::Random(f.rows()), hess);
    jac_nz = jac_nz.array() || (jac.array() != 0.0);
    hess_nz = hess_nz.array() || (hess.array() != 0.0);
  }
  PointPattern p;
  for (int c = 0; c < size; ++c) {
    for (int r = 0; r < f.rows(); ++r)
      if (jac_nz(r, c)) p.jacobian.emplace_back(r, c);
    for (int r = c; r < size; ++r)
      if (hess_nz(r, c) || hess_nz(c, r)) p.hessian.emplace_back(r, c);
  }
  return p;
}

PathConstraint::PathConstraint(std::string name, std::string phase, const PhaseLayout& layout,
                               std::shared_ptr<const PointFunction> function)
    : ConstraintSet(std::move(name), layout.points() * function->rows(), std::move(phase)),
      layout_(layout),
      f_(std::move(function)),
      pattern_(probePattern(*f_, layout.pointSize())) {}

Eigen::VectorXd PathConstraint::lowerBounds() const {
  return f_->lowerBounds().replicate(layout_.points(), 1);
}

Eigen::VectorXd PathConstraint::upperBounds() const {
  return f_->upperBounds().replicate(layout_.points(), 1);
}

void PathConstraint::values(const Eigen::VectorXd& x, Eigen::Ref<Eigen::VectorXd> g) const {
  const int m = f_->rows();
  for (int p = 0; p < layout_.points(); ++p) f_->evaluate(layout_.point(x, p), g.segment(p * m, m));
}

void PathConstraint::jacobian(const Eigen::VectorXd& x, Triplets& out) const {
  const int m = f_->rows();
  Eigen::MatrixXd block(m, layout_.pointSize());
  for (int p = 0; p < layout_.points(); ++p) {
    f_->jacobian(layout_.point(x, p), block);
    for (const auto& [r, c] : pattern_.jacobian)
      out.emplace_back(p * m + r, layout_.pointOffset(p) + c, block(r, c));
  }
}

void PathConstraint::hessian(const Eigen::VectorXd& x, const Eigen::VectorXd& lambda,
                             Triplets& out) const {
  const int m = f_->rows();
  Eigen::MatrixXd block(layout_.pointSize(), layout_.pointSize());
  for (int p = 0; p < layout_.points(); ++p) {
    f_->hessian(layout_.point(x, p), lambda.segment(p * m, m), block);
    appendPattern(block, pattern_.hessian, layout_.pointOffset(p), out);
  }
}

QuadratureCost::QuadratureCost(std::string name, const PhaseLayout& layout,
                               std::shared_ptr<const PointFunction> integrand,
                               Eigen::VectorXd weights)
    : CostTerm(std::move(name)),
      layout_(layout),
      f_(std::move(integrand)),
      weights_(weights.size() > 0 ? std::move(weights) : layout.quadratureWeights()),
      pattern_(probePattern(*f_, layout.pointSize())) {
  if (f_->rows() != 1) throw std::invalid_argument("a running cost integrand has one row");
  if (weights_.size() != layout_.points())
    throw std::invalid_argument("a running cost needs one quadrature weight per point");
}

double QuadratureCost::value(const Eigen::VectorXd& x) const {
  return layout_.durationAt(x) * unitDurationValue(x);
}

double QuadratureCost::unitDurationValue(const Eigen::VectorXd& x) const {
  double total = 0;
  Eigen::VectorXd f(1);
  for (int p = 0; p < layout_.points(); ++p) {
    f_->evaluate(layout_.point(x, p), f);
    total += weights_(p) * f(0);
  }
  return total;
}

// With a free T the cost T sum_p w_p L(v_p) also varies with T: d/dT = sum_p w_p L(v_p) and
// d2/dT dv_p = w_p dL/dv_p.
void QuadratureCost::gradient(const Eigen::VectorXd& x, Eigen::Ref<Eigen::VectorXd> grad) const {
  const double duration = layout_.durationAt(x);
  Eigen::MatrixXd jac(1, layout_.pointSize());
  for (int p = 0; p < layout_.points(); ++p) {
    f_->jacobian(layout_.point(x, p), jac);
    grad.segment(layout_.pointOffset(p), layout_.pointSize()) +=
        duration * weights_(p) * jac.row(0).transpose();
  }
  if (layout_.freeDuration()) grad(layout_.duration_index) += unitDurationValue(x);
}

void QuadratureCost::hessian(const Eigen::VectorXd& x, double factor, Triplets& out) const {
  const double scale = factor * layout_.durationAt(x);
  const int t = layout_.duration_index;
  Eigen::MatrixXd block(layout_.pointSize(), layout_.pointSize());
  Eigen::MatrixXd jac(1, layout_.pointSize());
  for (int p = 0; p < layout_.points(); ++p) {
    const Eigen::VectorXd v = layout_.point(x, p);
    f_->hessian(v, Eigen::VectorXd::Constant(1, scale * weights_(p)), block);
    appendPattern(block, pattern_.hessian, layout_.pointOffset(p), out);
    if (t < 0) continue;
    f_->jacobian(v, jac);
    for (const auto& [r, c] : pattern_.jacobian) {
      const int col = layout_.pointOffset(p) + c;
      out.emplace_back(std::max(t, col), std::min(t, col), factor * weights_(p) * jac(r, c));
    }
  }
}

}  // namespace gaitopt::ocp
