#include "ocp/shape/computed_torque_law.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>

namespace gaitopt::ocp {
namespace {

/// Blocks of y, in order.
enum Block { kTheta, kRate, kTorque, kThetaRef, kRateRef, kAccelerationRef, kBlocks };

PointLayout sspPoint(int n) {
  return PointLayout::biped(n, false, false);
}

void requireFullyActuated(const dynamics::Model& model) {
  for (const auto& joint : model.joints())
    if (!joint.actuated)
      throw std::invalid_argument(
          "the computed-torque law commands every joint: the robot has a passive joint");
}

}  // namespace

ComputedTorqueResidual::ComputedTorqueResidual(const dynamics::Model& nominal,
                                               const FeedbackGains& gains)
    : n_(nominal.nLinks()), dynamics_(nominal, sspPoint(nominal.nLinks())) {
  requireFullyActuated(nominal);
  const PointLayout l = sspPoint(n_);
  map_ = Eigen::MatrixXd::Zero(l.u.start + n_, kBlocks * n_);
  const auto put = [&](int row_start, Block b, double w) {
    map_.block(row_start, b * n_, n_, n_) += w * Eigen::MatrixXd::Identity(n_, n_);
  };
  put(l.q.start, kTheta, 1);
  put(l.v.start, kRate, 1);
  put(l.u.start, kTorque, 1);
  put(l.a.start, kAccelerationRef, 1);  // a_cmd = ddtheta_ref
  put(l.a.start, kThetaRef, gains.kp);  //   + kp (theta_ref - theta)
  put(l.a.start, kTheta, -gains.kp);
  put(l.a.start, kRateRef, gains.kd);  //   + kd (dtheta_ref - dtheta)
  put(l.a.start, kRate, -gains.kd);
}

void ComputedTorqueResidual::evaluate(const Eigen::VectorXd& y,
                                      Eigen::Ref<Eigen::VectorXd> f) const {
  dynamics_.evaluate(map_ * y, f);
}

void ComputedTorqueResidual::jacobian(const Eigen::VectorXd& y,
                                      Eigen::Ref<Eigen::MatrixXd> jac) const {
  Eigen::MatrixXd jv(n_, map_.rows());
  dynamics_.jacobian(map_ * y, jv);
  jac = jv * map_;
}

void ComputedTorqueResidual::hessian(const Eigen::VectorXd& y, const Eigen::VectorXd& weights,
                                     Eigen::Ref<Eigen::MatrixXd> hess) const {
  Eigen::MatrixXd hv(map_.rows(), map_.rows());
  dynamics_.hessian(map_ * y, weights, hv);
  hess = map_.transpose() * hv * map_;
}

ComputedTorqueLaw::ComputedTorqueLaw(std::string name, const Phase& variant, const Phase& reference,
                                     const dynamics::Model& nominal, const FeedbackGains& gains)
    : ConstraintSet(std::move(name), variant.layout.points() * nominal.nLinks(), variant.name()),
      residual_(nominal, gains),
      pattern_(probePattern(residual_, kBlocks * nominal.nLinks())) {
  if (variant.layout.points() != reference.layout.points())
    throw std::invalid_argument("a variant's feedback law needs the reference's mesh");
  const PointLayout& v = variant.point;
  const PointLayout& r = reference.point;
  for (int p = 0; p < variant.layout.points(); ++p) {
    const int vo = variant.layout.pointOffset(p), ro = reference.layout.pointOffset(p);
    std::vector<int> y;
    for (const auto& [offset, slice] :
         {std::pair{vo, v.q}, {vo, v.v}, {vo, v.u}, {ro, r.q}, {ro, r.v}, {ro, r.a}})
      for (int i = 0; i < slice.size; ++i) y.push_back(offset + slice.start + i);
    indices_.push_back(std::move(y));
  }
}

void ComputedTorqueLaw::values(const Eigen::VectorXd& x, Eigen::Ref<Eigen::VectorXd> g) const {
  const int m = residual_.rows();
  for (int p = 0; p < static_cast<int>(indices_.size()); ++p)
    residual_.evaluate(gather(x, indices_[static_cast<size_t>(p)]), g.segment(p * m, m));
}

void ComputedTorqueLaw::jacobian(const Eigen::VectorXd& x, Triplets& out) const {
  const int m = residual_.rows();
  Eigen::MatrixXd jac(m, kBlocks * m);
  for (int p = 0; p < static_cast<int>(indices_.size()); ++p) {
    const std::vector<int>& idx = indices_[static_cast<size_t>(p)];
    residual_.jacobian(gather(x, idx), jac);
    for (const auto& [r, c] : pattern_.jacobian)
      out.emplace_back(p * m + r, idx[static_cast<size_t>(c)], jac(r, c));
  }
}

void ComputedTorqueLaw::hessian(const Eigen::VectorXd& x, const Eigen::VectorXd& lambda,
                                Triplets& out) const {
  const int m = residual_.rows();
  Eigen::MatrixXd hess(kBlocks * m, kBlocks * m);
  for (int p = 0; p < static_cast<int>(indices_.size()); ++p) {
    const std::vector<int>& idx = indices_[static_cast<size_t>(p)];
    residual_.hessian(gather(x, idx), lambda.segment(p * m, m), hess);
    for (const auto& [r, c] : pattern_.hessian) {  // r >= c in y; the NLP's lower triangle
      const int a = idx[static_cast<size_t>(r)], b = idx[static_cast<size_t>(c)];
      out.emplace_back(std::max(a, b), std::min(a, b), hess(r, c));
    }
  }
}

}  // namespace gaitopt::ocp
