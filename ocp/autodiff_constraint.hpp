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
#include <algorithm>
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
  AutoDiffConstraint(std::string name, int rows, std::vector<int> indices, int nonlinear, Fn fn,
                     Eigen::VectorXd lower, Eigen::VectorXd upper)
      : ConstraintSet(std::move(name), rows),
        indices_(std::move(indices)),
        nonlinear_(nonlinear),
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
    const int k = nonlinear_;
    Eigen::Matrix<AD2, Eigen::Dynamic, 1> ya(m);
    for (int i = 0; i < m; ++i) {
      ya(i).value() = AD1(y(i), m, i);
      ya(i).derivatives().resize(k);
      for (int c = 0; c < k; ++c)
        ya(i).derivatives()(c) = AD1(i == c ? 1.0 : 0.0, Eigen::VectorXd::Zero(m));
    }
    const Eigen::Matrix<AD2, Eigen::Dynamic, 1> g = fn_(ya);
    AD2 s = AD2(0.0);
    for (int r = 0; r < rows(); ++r) s += lambda(r) * g(r);
    // Rows c < k of the Hessian hold every nonzero; emit each lower-triangle entry once.
    for (int c = 0; c < k; ++c)
      for (int d = 0; d < m; ++d) {
        if (d < k && indices_[c] < indices_[d]) continue;  // its mirror (d, c) is emitted
        const double h = c < s.derivatives().size() ? derivative(s.derivatives()(c), d) : 0.0;
        out.emplace_back(std::max(indices_[c], indices_[d]), std::min(indices_[c], indices_[d]), h);
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
  int nonlinear_;
  Fn fn_;
  Eigen::VectorXd lower_, upper_;
};

}  // namespace gaitopt::ocp
