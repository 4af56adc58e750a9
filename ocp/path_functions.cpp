#include "ocp/path_functions.hpp"

#include <cmath>

namespace gaitopt::ocp {
namespace {
constexpr double kInf = 1e20;  // Ipopt's infinity (nlp_upper_bound_inf)
}

void TorqueSquared::evaluate(const Eigen::VectorXd& v, Eigen::Ref<Eigen::VectorXd> f) const {
  f(0) = weight_ * v.segment(3 * n_, n_).squaredNorm();
}

void TorqueSquared::jacobian(const Eigen::VectorXd& v, Eigen::Ref<Eigen::MatrixXd> jac) const {
  jac.setZero();
  jac.block(0, 3 * n_, 1, n_) = 2 * weight_ * v.segment(3 * n_, n_).transpose();
}

void TorqueSquared::hessian(const Eigen::VectorXd&, const Eigen::VectorXd& w,
                            Eigen::Ref<Eigen::MatrixXd> hess) const {
  hess.setZero();
  hess.block(3 * n_, 3 * n_, n_, n_).diagonal().setConstant(2 * weight_ * w(0));
}

namespace {

/// Row j of M (Mu 2.41): dq_j = dtheta_j (j = 0) or dtheta_{j-1} - dtheta_j.
double jointRate(const Eigen::VectorXd& v, int n, int j) {
  return j == 0 ? v(n) : v(n + j - 1) - v(n + j);
}

}  // namespace

void WorkSplit::evaluate(const Eigen::VectorXd& v, Eigen::Ref<Eigen::VectorXd> f) const {
  for (int j = 0; j < n_; ++j)
    f(j) = v(3 * n_ + j) * jointRate(v, n_, j) - v(offset_ + j) + v(offset_ + n_ + j);
}

void WorkSplit::jacobian(const Eigen::VectorXd& v, Eigen::Ref<Eigen::MatrixXd> jac) const {
  jac.setZero();
  for (int j = 0; j < n_; ++j) {
    const double tau = v(3 * n_ + j);
    jac(j, 3 * n_ + j) = jointRate(v, n_, j);
    jac(j, n_ + j) = j == 0 ? tau : -tau;
    if (j > 0) jac(j, n_ + j - 1) = tau;
    jac(j, offset_ + j) = -1;
    jac(j, offset_ + n_ + j) = 1;
  }
}

void WorkSplit::hessian(const Eigen::VectorXd&, const Eigen::VectorXd& w,
                        Eigen::Ref<Eigen::MatrixXd> hess) const {
  hess.setZero();
  for (int j = 0; j < n_; ++j) {  // d2 (tau_j dq_j) / dtau_j ddtheta_k = M_jk
    const int t = 3 * n_ + j;
    hess(t, n_ + j) = hess(n_ + j, t) = j == 0 ? w(j) : -w(j);
    if (j > 0) hess(t, n_ + j - 1) = hess(n_ + j - 1, t) = w(j);
  }
}

void KneeDirection::evaluate(const Eigen::VectorXd& v, Eigen::Ref<Eigen::VectorXd> f) const {
  f << v(0) - v(1), v(n_ - 2) - v(n_ - 1);
}

void KneeDirection::jacobian(const Eigen::VectorXd&, Eigen::Ref<Eigen::MatrixXd> jac) const {
  jac.setZero();
  jac(0, 0) = 1;
  jac(0, 1) = -1;
  jac(1, n_ - 2) = 1;
  jac(1, n_ - 1) = -1;
}

Eigen::VectorXd KneeDirection::lowerBounds() const {
  return Eigen::Vector2d(0, -kInf);
}
Eigen::VectorXd KneeDirection::upperBounds() const {
  return Eigen::Vector2d(kInf, 0);
}

void SwingHeight::evaluate(const Eigen::VectorXd& v, Eigen::Ref<Eigen::VectorXd> f) const {
  const auto& w = model_->tipWeights();
  f(0) = 0;
  for (int j = 0; j < model_->nLinks(); ++j) f(0) += w(j) * std::cos(v(j));
}

void SwingHeight::jacobian(const Eigen::VectorXd& v, Eigen::Ref<Eigen::MatrixXd> jac) const {
  const auto& w = model_->tipWeights();
  jac.setZero();
  for (int j = 0; j < model_->nLinks(); ++j) jac(0, j) = -w(j) * std::sin(v(j));
}

void SwingHeight::hessian(const Eigen::VectorXd& v, const Eigen::VectorXd& weights,
                          Eigen::Ref<Eigen::MatrixXd> hess) const {
  const auto& w = model_->tipWeights();
  hess.setZero();
  for (int j = 0; j < model_->nLinks(); ++j) hess(j, j) = -weights(0) * w(j) * std::cos(v(j));
}

SwingClearance::SwingClearance(const dynamics::Model& model, const PhaseLayout& layout,
                               const ClearanceProfile& profile)
    : PathConstraint("ssp_clearance", layout, std::make_shared<SwingHeight>(model)),
      lower_(layout.points()) {
  for (int p = 0; p < layout.points(); ++p) lower_(p) = profile.at(layout.time(p, 1.0));
}

}  // namespace gaitopt::ocp
