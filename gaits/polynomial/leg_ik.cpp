#include "gaits/polynomial/leg_ik.hpp"

#include <cmath>
#include <stdexcept>

#include <fmt/format.h>
#include <Eigen/LU>

namespace gaitopt::gaits {
namespace {

Eigen::Vector2d unit(double angle) {
  return {std::sin(angle), std::cos(angle)};
}

/// A leg of this length is horizontal when its height is below this fraction of it.
constexpr double kHorizontal = 1e-6;

bool withinReach(double l_a, double l_b, double dist) {
  return dist > std::abs(l_a - l_b) && dist < l_a + l_b;
}

/// Horizontal offset of the knee from the proximal-distal line, at the knee's height.
double kneeOffset(const Eigen::Vector2d& r, const Eigen::Vector2d& knee) {
  return knee(0) - r(0) * knee(1) / r(1);
}

}  // namespace

bool legCanReach(double l_a, double l_b, const Eigen::Vector2d& r) {
  const double dist = r.norm();
  return withinReach(l_a, l_b, dist) && std::abs(r(1)) >= kHorizontal * dist;
}

LegAngles legInverseKinematics(double l_a, double l_b, const PointMotion& r, KneeDirection knee) {
  const double dist = r.pos.norm();
  if (!withinReach(l_a, l_b, dist))
    throw std::domain_error(fmt::format(
        "leg cannot reach: hip-tip distance {:.4f} m outside the open range ({:.4f}, {:.4f}) m",
        dist, std::abs(l_a - l_b), l_a + l_b));
  if (std::abs(r.pos(1)) < kHorizontal * dist)
    throw std::domain_error("leg is horizontal: the knee direction is undefined");

  // Law of cosines: angle between r and link a (Mu 3.24 solves the same triangle).
  const double phi = std::atan2(r.pos(0), r.pos(1));
  const double gamma = std::acos((l_a * l_a + dist * dist - l_b * l_b) / (2 * l_a * dist));
  const double sign = knee == KneeDirection::kForward ? 1.0 : -1.0;
  double alpha = phi + gamma;
  Eigen::Vector2d u_a = unit(alpha);
  if (sign * kneeOffset(r.pos, l_a * u_a) < 0) {
    alpha = phi - gamma;
    u_a = unit(alpha);
  }
  const Eigen::Vector2d rest = r.pos - l_a * u_a;
  const double beta = std::atan2(rest(0), rest(1));
  // unit(beta), not rest / l_b: equal in exact arithmetic, but the cost-of-transport solve
  // lands in another local optimum when the guess's rates move by 1e-13.
  const Eigen::Vector2d u_b = unit(beta);

  // Columns d(l u)/dtheta = l (cos, -sin): u rotated a quarter turn.
  Eigen::Matrix2d jac;
  jac.col(0) = l_a * Eigen::Vector2d(u_a(1), -u_a(0));
  jac.col(1) = l_b * Eigen::Vector2d(u_b(1), -u_b(0));
  const auto lu = jac.partialPivLu();
  LegAngles out;
  out.theta = {alpha, beta};
  out.dtheta = lu.solve(r.vel);
  // Jdot dtheta = -l_a alphadot^2 u(alpha) - l_b betadot^2 u(beta).
  const Eigen::Vector2d bias =
      -l_a * out.dtheta(0) * out.dtheta(0) * u_a - l_b * out.dtheta(1) * out.dtheta(1) * u_b;
  out.ddtheta = lu.solve(r.acc - bias);
  return out;
}

}  // namespace gaitopt::gaits
