#include "dynamics/impact/impact.hpp"

#include <cmath>

#include <Eigen/LU>

#include "dynamics/kinematics.hpp"

namespace gaitopt::dynamics {
namespace {

/// Sum of the masses of links first..last (inclusive, 0-based; empty when last < first).
double massRange(const Model& model, int first, int last) {
  double m = 0;
  for (int k = first; k <= last; ++k) m += model.link(k).mass;
  return m;
}

bool withinCone(const Vec2d& impulse, double mu) {
  return std::abs(impulse(0)) < mu * std::abs(impulse(1));
}

/// V of Mu (2.29b): total linear momentum per unit dtheta with B fixed, m J_com (2 x n).
Mat2Xd momentumMap(const Model& model, const VecD& theta) {
  return model.totalMass() * pointJacobian(model.totalComWeights(), theta);
}

}  // namespace

MatD impactW(const Model& model, const VecD& theta) {
  const int n = model.nLinks();
  MatD w = MatD::Zero(n, n);
  for (int i = 0; i < n; ++i) {
    const Link& li = model.link(i);
    const double ai = li.a();
    w(i, i) = li.inertia - li.mass * li.com * (ai * li.length - li.com);
    for (int j = 0; j < i; ++j) {
      const Link& lj = model.link(j);
      const double aj = lj.a();
      w(i, j) = -(ai * lj.mass * lj.com * li.length +
                  aj * li.mass * (ai * li.length - li.com) * lj.length +
                  ai * aj * massRange(model, j + 1, i - 1) * li.length * lj.length) *
                std::cos(theta(i) - theta(j));
    }
  }
  return w;
}

Eigen::Matrix<double, Eigen::Dynamic, 2, 0, kMaxLinks, 2> impactU(const Model& model,
                                                                  const VecD& theta) {
  const int n = model.nLinks();
  Eigen::Matrix<double, Eigen::Dynamic, 2, 0, kMaxLinks, 2> u(n, 2);
  for (int i = 0; i < n; ++i) {
    const Link& li = model.link(i);
    const double c =
        -li.mass * (li.a() * li.length - li.com) - massRange(model, 0, i - 1) * li.a() * li.length;
    u(i, 0) = c * std::cos(theta(i));
    u(i, 1) = -c * std::sin(theta(i));
  }
  return u;
}

ImpactResult doubleImpact(const Model& model, const VecD& theta, const VecD& dtheta_minus) {
  const MatD w = impactW(model, theta);
  const Mat2Xd jac = pointJacobian(model.tipWeights(), theta);
  const auto w_lu = w.partialPivLu();
  const MatD w_inv_jt = w_lu.solve(MatD(jac.transpose()));
  const Eigen::Matrix2d jwj = jac * w_inv_jt;
  ImpactResult out;
  out.impulse_trailing = jwj.inverse() * (jac * dtheta_minus);                     // (2.27)
  const VecD delta = -w_inv_jt * out.impulse_trailing;                             // (2.25)
  out.dtheta_plus = dtheta_minus + delta;                                          // (2.28)
  out.impulse_leading = momentumMap(model, theta) * delta - out.impulse_trailing;  // (2.29a)
  out.trailing_velocity.setZero();
  out.unilateral_ok = out.impulse_trailing(1) > 0;  // (2.31a)
  out.friction_ok = withinCone(out.impulse_trailing, model.friction()) &&
                    withinCone(out.impulse_leading, model.friction());  // (2.31b-c)
  return out;
}

ImpactResult singleImpact(const Model& model, const VecD& theta, const VecD& dtheta_minus) {
  const Mat2Xd jac = pointJacobian(model.tipWeights(), theta);
  const auto u = impactU(model, theta);
  const MatD w_uj = impactW(model, theta) - u * jac;                     // (2.34a), by product
  const Vec2d tip_velocity = jac * dtheta_minus;                         // Xdot_e^-
  const VecD delta = w_uj.partialPivLu().solve(VecD(u * tip_velocity));  // (2.35a)
  ImpactResult out;
  out.dtheta_plus = dtheta_minus + delta;               // (2.36a)
  out.trailing_velocity = -jac * delta - tip_velocity;  // (2.35b)
  out.impulse_leading =
      model.totalMass() * out.trailing_velocity + momentumMap(model, theta) * delta;  // (2.35c)
  out.impulse_trailing.setZero();
  out.unilateral_ok = out.trailing_velocity(1) > 0;                     // (2.37a)
  out.friction_ok = withinCone(out.impulse_leading, model.friction());  // (2.37b)
  return out;
}

ImpactType classifyImpact(const Model& model, const VecD& theta, const VecD& dtheta_minus) {
  const bool double_ok = doubleImpact(model, theta, dtheta_minus).unilateral_ok;
  const bool single_ok = singleImpact(model, theta, dtheta_minus).unilateral_ok;
  if (double_ok && !single_ok) return ImpactType::kDouble;
  if (single_ok && !double_ok) return ImpactType::kSingle;
  return double_ok ? ImpactType::kEither : ImpactType::kNeither;
}

const char* toString(ImpactType type) {
  switch (type) {
    case ImpactType::kDouble:
      return "double";
    case ImpactType::kSingle:
      return "single";
    case ImpactType::kEither:
      return "either";
    case ImpactType::kNeither:
      return "neither";
  }
  return "unknown";
}

}  // namespace gaitopt::dynamics
