#pragma once
/// @file autodiff_constraint.hpp
/// A constraint set g(y) on a few variables y = x[indices] (link constraints: impact,
/// relabelling, boundary conditions), differentiated by autodiff.hpp.
#include <algorithm>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "ocp/transcription/autodiff.hpp"
#include "ocp/transcription/nlp.hpp"

namespace gaitopt::ocp {

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
        upper_(std::move(upper)) {
    if (indices_.size() > static_cast<size_t>(kMaxAdInputs) || nonlinear_ > gaitopt::kMaxLinks)
      throw std::logic_error(fmt::format(
          "link constraint '{}' has {} variables ({} nonlinear); autodiff.hpp bounds them at {} "
          "({})",
          this->name(), indices_.size(), nonlinear_, kMaxAdInputs, gaitopt::kMaxLinks));
  }

  Eigen::VectorXd lowerBounds() const override { return lower_; }
  Eigen::VectorXd upperBounds() const override { return upper_; }

  void values(const Eigen::VectorXd& x, Eigen::Ref<Eigen::VectorXd> g) const override {
    g = fn_(gather(x, indices_));
  }

  void jacobian(const Eigen::VectorXd& x, Triplets& out) const override {
    const Eigen::MatrixXd jac = adJacobian(fn_, gather(x, indices_), rows());
    for (int r = 0; r < rows(); ++r)
      for (int c = 0; c < jac.cols(); ++c) out.emplace_back(r, indices_[c], jac(r, c));
  }

  void hessian(const Eigen::VectorXd& x, const Eigen::VectorXd& lambda,
               Triplets& out) const override {
    const Eigen::MatrixXd h = adHessian(fn_, gather(x, indices_), lambda, nonlinear_);
    // Rows c < nonlinear hold every nonzero; emit each lower-triangle entry once.
    const int m = static_cast<int>(h.cols());
    for (int c = 0; c < nonlinear_; ++c)
      for (int d = 0; d < m; ++d) {
        if (d < nonlinear_ && indices_[c] < indices_[d]) continue;  // its mirror is emitted
        out.emplace_back(std::max(indices_[c], indices_[d]), std::min(indices_[c], indices_[d]),
                         h(c, d));
      }
  }

 private:
  std::vector<int> indices_;
  int nonlinear_;
  Fn fn_;
  Eigen::VectorXd lower_, upper_;
};

/// `a` followed by `b`: the stacked variables of a link constraint.
inline std::vector<int> concat(std::vector<int> a, const std::vector<int>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

/// Adds a link constraint lo <= fn(x[idx]) <= hi (rows rows, phase tag kLinkPhase); the functor
/// is affine in all but the first `nonlinear` of its variables.
template <class Fn>
void addLink(Nlp& nlp, const std::string& name, int rows, std::vector<int> idx, int nonlinear,
             Fn fn, double lo = 0.0, double hi = 0.0) {
  nlp.addConstraint(std::make_unique<AutoDiffConstraint<Fn>>(
      name, rows, std::move(idx), nonlinear, fn, Eigen::VectorXd::Constant(rows, lo),
      Eigen::VectorXd::Constant(rows, hi)));
}

}  // namespace gaitopt::ocp
