#include "gaits/leg_ik.hpp"

#include <cmath>
#include <stdexcept>

#include <fmt/format.h>
#include <Eigen/LU>

namespace gaitopt::gaits {
namespace {

Eigen::Vector2d unit(double angle) {
  return {std::sin(angle), std::cos(angle)};
}
Eigen::Vector2d unitDerivative(double angle) {
  return {std::cos(angle), -std::sin(angle)};
}

/// Horizontal offset of the knee from the proximal-distal line, at the knee's height.
double kneeOffset(const Eigen::Vector2d& r, const Eigen::Vector2d& knee) {
  return knee(0) - r(0) * knee(1) / r(1);
}

}  // namespace

LegAngles legInverseKinematics(double l_a, double l_b, const PointMotion& r, KneeDirection knee) {
  const double dist = r.pos.norm();
  if (!(dist > std::abs(l_a - l_b) && dist < l_a + l_b))
    throw std::domain_error(fmt::format(
        "leg cannot reach: hip-tip distance {:.4f} m outside the open range ({:.4f}, {:.4f}) m",
        dist, std::abs(l_a - l_b), l_a + l_b));
  if (std::abs(r.pos(1)) < 1e-6 * dist)
    throw std::domain_error("leg is horizontal: the knee direction is undefined");

  // Law of cosines: angle between r and link a (Mu 3.24 solves the same triangle).
  const double phi = std::atan2(r.pos(0), r.pos(1));
  const double gamma = std::acos((l_a * l_a + dist * dist - l_b * l_b) / (2 * l_a * dist));
  const double sign = knee == KneeDirection::kForward ? 1.0 : -1.0;
  double alpha = phi + gamma;
  if (sign * kneeOffset(r.pos, l_a * unit(alpha)) < 0) alpha = phi - gamma;
  const Eigen::Vector2d rest = r.pos - l_a * unit(alpha);
  const double beta = std::atan2(rest(0), rest(1));

  Eigen::Matrix2d jac;
  jac.col(0) = l_a * unitDerivative(alpha);
  jac.col(1) = l_b * unitDerivative(beta);
  const auto lu = jac.partialPivLu();
  LegAngles out;
  out.theta = {alpha, beta};
  out.dtheta = lu.solve(r.vel);
  // Jdot dtheta = -l_a alphadot^2 u(alpha) - l_b betadot^2 u(beta).
  const Eigen::Vector2d bias = -l_a * out.dtheta(0) * out.dtheta(0) * unit(alpha) -
                               l_b * out.dtheta(1) * out.dtheta(1) * unit(beta);
  out.ddtheta = lu.solve(r.acc - bias);
  return out;
}

}  // namespace gaitopt::gaits
