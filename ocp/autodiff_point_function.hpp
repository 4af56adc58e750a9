#pragma once
/// @file autodiff_point_function.hpp
/// A PointFunction written once as a templated functor of the whole point v, differentiated by
/// autodiff.hpp; `nonlinear` counts the leading entries of v the function is nonlinear in.
#include <utility>

#include "ocp/autodiff.hpp"
#include "ocp/point_function.hpp"

namespace gaitopt::ocp {

template <class Fn>
class AutoDiffPointFunction : public PointFunction {
 public:
  AutoDiffPointFunction(int rows, int nonlinear, Fn fn, Eigen::VectorXd lower,
                        Eigen::VectorXd upper)
      : rows_(rows),
        nonlinear_(nonlinear),
        fn_(std::move(fn)),
        lower_(std::move(lower)),
        upper_(std::move(upper)) {}

  int rows() const override { return rows_; }
  void evaluate(const Eigen::VectorXd& v, Eigen::Ref<Eigen::VectorXd> f) const override {
    f = fn_(v);
  }
  void jacobian(const Eigen::VectorXd& v, Eigen::Ref<Eigen::MatrixXd> jac) const override {
    jac = adJacobian(fn_, v, rows_);
  }
  void hessian(const Eigen::VectorXd& v, const Eigen::VectorXd& w,
               Eigen::Ref<Eigen::MatrixXd> hess) const override {
    hess = adHessian(fn_, v, w, nonlinear_);
  }
  Eigen::VectorXd lowerBounds() const override { return lower_; }
  Eigen::VectorXd upperBounds() const override { return upper_; }

 private:
  int rows_;
  int nonlinear_;
  Fn fn_;
  Eigen::VectorXd lower_, upper_;
};

}  // namespace gaitopt::ocp
