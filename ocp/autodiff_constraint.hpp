#pragma once
/// @file autodiff_constraint.hpp
/// A constraint set g(y) on a few variables y = x[indices], written once as a templated functor
/// and differentiated exactly by forward-mode automatic differentiation (Eigen's
/// AutoDiffScalar): first order for the Jacobian, nested (forward over forward) for the Hessian
/// of lambda^T g. For small link constraints (impact, relabelling, boundary conditions), where
/// a hand-written Hessian would be long and fragile.
///
/// The functor: template <class S> Eigen::Matrix<S, Eigen::Dynamic, 1> operator()(
///                  const Eigen::Matrix<S, Eigen::Dynamic, 1>& y) const;
#include <utility>
#include <vector>

#include <Eigen/Core>
#include <unsupported/Eigen/AutoDiff>

#include "ocp/nlp.hpp"

namespace gaitopt::ocp {

using AD1 = Eigen::AutoDiffScalar<Eigen::VectorXd>;
using AD2 = Eigen::AutoDiffScalar<Eigen::Matrix<AD1, Eigen::Dynamic, 1>>;

template <class Fn>
class AutoDiffConstraint : public ConstraintSet {
 public:
  AutoDiffConstraint(std::string name, int rows, std::vector<int> indices, Fn fn,
                     Eigen::VectorXd lower, Eigen::VectorXd upper)
      : ConstraintSet(std::move(name), rows),
        indices_(std::move(indices)),
        fn_(std::move(fn)),
        lower_(std::move(lower)),
        upper_(std::move(upper)) {}

  Eigen::VectorXd lowerBounds() const override { return lower_; }
  Eigen::VectorXd upperBounds() const override { return upper_; }

  void values(const Eigen::VectorXd& x, Eigen::Ref<Eigen::VectorXd> g) const override {
    g = fn_(gather(x));
  }

  void jacobian(const Eigen::VectorXd& x, Triplets& out) const override {
    const Eigen::VectorXd y = gather(x);
    const int m = static_cast<int>(y.size());
    Eigen::Matrix<AD1, Eigen::Dynamic, 1> ya(m);
    for (int i = 0; i < m; ++i) ya(i) = AD1(y(i), m, i);
    const Eigen::Matrix<AD1, Eigen::Dynamic, 1> g = fn_(ya);
    for (int r = 0; r < rows(); ++r)
      for (int c = 0; c < m; ++c) out.emplace_back(r, indices_[c], derivative(g(r), c));
  }

  void hessian(const Eigen::VectorXd& x, const Eigen::VectorXd& lambda,
               Triplets& out) const override {
    const Eigen::VectorXd y = gather(x);
    const int m = static_cast<int>(y.size());
    Eigen::Matrix<AD2, Eigen::Dynamic, 1> ya(m);
    for (int i = 0; i < m; ++i) {
      ya(i).value() = AD1(y(i), m, i);
      ya(i).derivatives() = Eigen::Matrix<AD1, Eigen::Dynamic, 1>::Zero(m);
      for (int k = 0; k < m; ++k)
        ya(i).derivatives()(k) = AD1(i == k ? 1.0 : 0.0, Eigen::VectorXd::Zero(m));
    }
    const Eigen::Matrix<AD2, Eigen::Dynamic, 1> g = fn_(ya);
    AD2 s = AD2(0.0);
    for (int r = 0; r < rows(); ++r) s += lambda(r) * g(r);
    for (int c = 0; c < m; ++c)
      for (int d = 0; d < m; ++d) {
        const double h = c < s.derivatives().size() ? derivative(s.derivatives()(c), d) : 0.0;
        const int row = indices_[c], col = indices_[d];
        if (row >= col) out.emplace_back(row, col, h);
      }
  }

 private:
  Eigen::VectorXd gather(const Eigen::VectorXd& x) const {
    Eigen::VectorXd y(static_cast<Eigen::Index>(indices_.size()));
    for (size_t i = 0; i < indices_.size(); ++i) y(static_cast<Eigen::Index>(i)) = x(indices_[i]);
    return y;
  }
  /// d/dy_c of a first-order scalar; constants carry an empty derivative vector.
  static double derivative(const AD1& a, int c) {
    return c < a.derivatives().size() ? a.derivatives()(c) : 0.0;
  }

  std::vector<int> indices_;
  Fn fn_;
  Eigen::VectorXd lower_, upper_;
};

}  // namespace gaitopt::ocp
