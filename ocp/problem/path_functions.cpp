#include "ocp/problem/path_functions.hpp"

#include <cmath>

namespace gaitopt::ocp {
void TorqueSquared::evaluate(const Eigen::VectorXd& v, Eigen::Ref<Eigen::VectorXd> f) const {
  f(0) = weight_ * point_.u.of(v).squaredNorm();
}

void TorqueSquared::jacobian(const Eigen::VectorXd& v, Eigen::Ref<Eigen::MatrixXd> jac) const {
  jac.setZero();
  point_.u.of(jac.row(0)) = 2 * weight_ * point_.u.of(v).transpose();
}

void TorqueSquared::hessian(const Eigen::VectorXd&, const Eigen::VectorXd& w,
                            Eigen::Ref<Eigen::MatrixXd> hess) const {
  hess.setZero();
  const Slice& u = point_.u;
  hess.block(u.start, u.start, u.size, u.size).diagonal().setConstant(2 * weight_ * w(0));
}

namespace {

/// Row j of M (Mu 2.41): dq_j = dtheta_j (j = 0) or dtheta_{j-1} - dtheta_j.
double jointRate(const Eigen::VectorXd& v, const PointLayout& l, int j) {
  return j == 0 ? v(l.v[0]) : v(l.v[j - 1]) - v(l.v[j]);
}

}  // namespace

void WorkSplit::evaluate(const Eigen::VectorXd& v, Eigen::Ref<Eigen::VectorXd> f) const {
  const PointLayout& l = point_;
  for (int j = 0; j < l.n; ++j)
    f(j) = v(l.u[j]) * jointRate(v, l, j) - v(l.work_plus[j]) + v(l.work_minus[j]);
}

void WorkSplit::jacobian(const Eigen::VectorXd& v, Eigen::Ref<Eigen::MatrixXd> jac) const {
  const PointLayout& l = point_;
  jac.setZero();
  for (int j = 0; j < l.n; ++j) {
    const double tau = v(l.u[j]);
    jac(j, l.u[j]) = jointRate(v, l, j);
    jac(j, l.v[j]) = j == 0 ? tau : -tau;
    if (j > 0) jac(j, l.v[j - 1]) = tau;
    jac(j, l.work_plus[j]) = -1;
    jac(j, l.work_minus[j]) = 1;
  }
}

void WorkSplit::hessian(const Eigen::VectorXd&, const Eigen::VectorXd& w,
                        Eigen::Ref<Eigen::MatrixXd> hess) const {
  const PointLayout& l = point_;
  hess.setZero();
  for (int j = 0; j < l.n; ++j) {  // d2 (tau_j dq_j) / dtau_j ddtheta_k = M_jk
    const int t = l.u[j];
    hess(t, l.v[j]) = hess(l.v[j], t) = j == 0 ? w(j) : -w(j);
    if (j > 0) hess(t, l.v[j - 1]) = hess(l.v[j - 1], t) = w(j);
  }
}

JointRateLimits::JointRateLimits(const dynamics::Model& model, const PointLayout& point)
    : point_(point), limit_(point.n) {
  for (int j = 0; j < point.n; ++j)
    limit_(j) = model.joints()[static_cast<size_t>(j)].velocity_limit;
}

void JointRateLimits::evaluate(const Eigen::VectorXd& v, Eigen::Ref<Eigen::VectorXd> f) const {
  for (int j = 0; j < point_.n; ++j) f(j) = jointRate(v, point_, j);
}

void JointRateLimits::jacobian(const Eigen::VectorXd&, Eigen::Ref<Eigen::MatrixXd> jac) const {
  jac.setZero();
  for (int j = 0; j < point_.n; ++j) {  // row j of M (2.41)
    jac(j, point_.v[j]) = j == 0 ? 1.0 : -1.0;
    if (j > 0) jac(j, point_.v[j - 1]) = 1.0;
  }
}

void KneeDirection::evaluate(const Eigen::VectorXd& v, Eigen::Ref<Eigen::VectorXd> f) const {
  const Slice& q = point_.q;
  f << v(q[0]) - v(q[1]), v(q[q.size - 2]) - v(q[q.size - 1]);
}

void KneeDirection::jacobian(const Eigen::VectorXd&, Eigen::Ref<Eigen::MatrixXd> jac) const {
  const Slice& q = point_.q;
  jac.setZero();
  jac(0, q[0]) = 1;
  jac(0, q[1]) = -1;
  jac(1, q[q.size - 2]) = 1;
  jac(1, q[q.size - 1]) = -1;
}

Eigen::VectorXd KneeDirection::lowerBounds() const {
  return Eigen::Vector2d(min_stance_, -max_swing_);
}
Eigen::VectorXd KneeDirection::upperBounds() const {
  return Eigen::Vector2d(max_stance_, 0);
}

void SwingHeight::evaluate(const Eigen::VectorXd& v, Eigen::Ref<Eigen::VectorXd> f) const {
  const auto& w = model_->tipWeights();
  f(0) = 0;
  for (int j = 0; j < model_->nLinks(); ++j) f(0) += w(j) * std::cos(v(point_.q[j]));
}

void SwingHeight::jacobian(const Eigen::VectorXd& v, Eigen::Ref<Eigen::MatrixXd> jac) const {
  const auto& w = model_->tipWeights();
  jac.setZero();
  for (int j = 0; j < model_->nLinks(); ++j) {
    const int q = point_.q[j];
    jac(0, q) = -w(j) * std::sin(v(q));
  }
}

void SwingHeight::hessian(const Eigen::VectorXd& v, const Eigen::VectorXd& weights,
                          Eigen::Ref<Eigen::MatrixXd> hess) const {
  const auto& w = model_->tipWeights();
  hess.setZero();
  for (int j = 0; j < model_->nLinks(); ++j) {
    const int q = point_.q[j];
    hess(q, q) = -weights(0) * w(j) * std::cos(v(q));
  }
}

SwingClearance::SwingClearance(const dynamics::Model& model, const Phase& phase,
                               const ClearanceProfile& profile)
    : PathConstraint(phase.name() + "_clearance", phase.name(), phase.layout,
                     std::make_shared<SwingHeight>(model, phase.point)),
      lower_(phase.layout.points()) {
  for (int p = 0; p < phase.layout.points(); ++p) lower_(p) = profile.at(phase.layout.time(p, 1.0));
}

}  // namespace gaitopt::ocp
