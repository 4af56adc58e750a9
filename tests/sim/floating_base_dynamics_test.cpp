// The free-base equations of motion the compliant and LCP walks integrate
// (dynamics/floating_base_dynamics.hpp): without contact and torque they conserve energy,
// horizontal momentum and the angular momentum about the CoM, the vertical momentum falls at
// m g, and a chain at rest falls as a rigid body at g; on a slope (ground frame, gravity g_vec
// rotated) the momentum rate is m g_vec.
#include <cmath>
#include <utility>

#include <gtest/gtest.h>

#include <fmt/format.h>
#include <Eigen/Cholesky>

#include "dynamics/energy.hpp"
#include "dynamics/floating_base_dynamics.hpp"
#include "dynamics/model_variation.hpp"
#include "five_link_gait.hpp"
#include "sim/walk/event_integrator.hpp"

namespace gaitopt::sim {
namespace {

using dynamics::Model;

/// xdot = (v, D_ext^-1 (-b)): the free chain, no torque, no contact.
Eigen::VectorXd freeFlight(const Model& m, const Eigen::VectorXd& x) {
  const int n = m.nLinks(), nq = n + 2;
  const auto fb = dynamics::floatingBaseDynamics(m, x.segment(2, n), x.tail(n));
  Eigen::VectorXd xdot(2 * nq);
  xdot << x.tail(nq), fb.mass.llt().solve(-fb.bias);
  return xdot;
}

double energy(const Model& m, const Eigen::VectorXd& x) {
  const int n = m.nLinks();
  const VecD theta = x.segment(2, n), dtheta = x.tail(n);
  const Vec2d base_velocity = x.segment<2>(n + 2);
  return dynamics::kineticEnergy<double>(m, theta, dtheta, base_velocity) +
         dynamics::potentialEnergy<double>(m, theta) -
         m.totalMass() * m.gravityAcceleration().dot(x.head<2>());
}

Vec2d momentum(const Model& m, const Eigen::VectorXd& x) {
  const int n = m.nLinks();
  return dynamics::linearMomentum<double>(m, VecD(x.segment(2, n)), VecD(x.tail(n)),
                                          Vec2d(x.segment<2>(n + 2)));
}

/// CoM position and velocity of link i in the world, from the link geometry rather than the
/// model's weights: the proximal joint of link i is B plus a_j l_j u_j of the links before it,
/// the CoM lies d_i further along u_i (Mu 2.1, 2.2), u = (sin theta, cos theta); velocities by
/// du/dt = dtheta (cos theta, -sin theta) [m, m/s].
std::pair<Vec2d, Vec2d> linkComState(const Model& m, const Eigen::VectorXd& x, int i) {
  const int n = m.nLinks();
  Vec2d r = x.head<2>(), v = x.segment<2>(n + 2);
  for (int j = 0; j <= i; ++j) {
    const double theta = x(2 + j), rate = x(n + 4 + j);
    const double reach = j < i ? m.link(j).a() * m.link(j).length : m.link(j).com;
    r += reach * Vec2d(std::sin(theta), std::cos(theta));
    v += reach * rate * Vec2d(std::cos(theta), -std::sin(theta));
  }
  return {r, v};
}

/// Angular momentum about the whole-body CoM, counter-clockwise positive [kg m^2/s]:
/// L = sum_i m_i (r_i - r_c) x (v_i - v_c) + I_i omega_i. theta is clockwise positive
/// (conventions.hpp), so a link turns at omega_i = -dtheta_i. Gravity exerts no moment about
/// the CoM, so L is conserved in flight.
double spinAboutCom(const Model& m, const Eigen::VectorXd& x) {
  const int n = m.nLinks();
  Vec2d rc = Vec2d::Zero(), vc = Vec2d::Zero();
  for (int i = 0; i < n; ++i) {
    const auto [r, v] = linkComState(m, x, i);
    rc += m.link(i).mass / m.totalMass() * r;
    vc += m.link(i).mass / m.totalMass() * v;
  }
  double l = 0;
  for (int i = 0; i < n; ++i) {
    const auto [r, v] = linkComState(m, x, i);
    const Vec2d dr = r - rc, dv = v - vc;
    l += m.link(i).mass * (dr(0) * dv(1) - dr(1) * dv(0)) - m.link(i).inertia * x(n + 4 + i);
  }
  return l;
}

/// Worst deviations over 1 s of RK4 flight of a tumbling robot: energy [J], momentum from
/// p0 + m g_vec t [kg m/s] (per component) and angular momentum about the CoM [kg m^2/s].
struct FlightErrors {
  double energy = 0, px = 0, py = 0, spin = 0;
  double spin0 = 0;  ///< the conserved angular momentum itself
};

FlightErrors tumble(const Model& m) {
  const int n = m.nLinks();
  Eigen::VectorXd x(2 * (n + 2));
  // A tumbling robot: base moving up and forward, every link turning (rad/s).
  x << 0.1, 0.8, 0.1, 0.3, -0.05, 3.0, 2.9,  //
      0.5, 1.5, -1.0, 2.0, 0.5, -3.0, 4.0;
  const double e0 = energy(m, x);
  const Vec2d p0 = momentum(m, x);
  FlightErrors worst;
  worst.spin0 = spinAboutCom(m, x);
  const Vec2d weight = m.totalMass() * m.gravityAcceleration();
  const double h = 1e-3, duration = 1.0;
  const Rhs f = [&](double, const Eigen::VectorXd& s) { return freeFlight(m, s); };
  for (int k = 1; k * h <= duration + 1e-12; ++k) {
    x = rk4Step(f, 0.0, x, h);
    const Vec2d p = momentum(m, x) - (p0 + weight * (k * h));
    worst.energy = std::max(worst.energy, std::abs(energy(m, x) - e0));
    worst.px = std::max(worst.px, std::abs(p(0)));
    worst.py = std::max(worst.py, std::abs(p(1)));
    worst.spin = std::max(worst.spin, std::abs(spinAboutCom(m, x) - worst.spin0));
  }
  return worst;
}

TEST(FloatingBaseDynamics, FreeChainConservesEnergyAndAngularMomentumAndFallsWithItsWeight) {
  const FlightErrors e = tumble(test::fiveLinkRobot());
  RecordProperty("energy_drift_J", fmt::format("{:.2e}", e.energy));
  RecordProperty("angular_momentum", fmt::format("{:.4f}", e.spin0));
  RecordProperty("angular_momentum_drift", fmt::format("{:.2e}", e.spin));
  // RK4's global error is O(h^4): the drift measured 1.3e-12 kg m^2/s at h = 1 ms and
  // 3.4e-10 at 4 ms (ratio 260 = 4^4), so the bound is 8 times the 1 ms value. The spin with
  // the wrong sign on the links' own rotation, +I_i dtheta_i, drifts by 2.6e-2.
  EXPECT_GT(std::abs(e.spin0), 0.1);  // the robot does tumble
  EXPECT_LT(e.spin, 1e-11);
  // RK4 at 1 ms: the drift is O(h^4); 1e-6 J against kinetic energies of ~100 J.
  EXPECT_LT(e.energy, 1e-6);
  // Momentum is linear in the state's velocities and its rate is exact in the dynamics, so RK4
  // keeps it to rounding.
  EXPECT_LT(e.px, 1e-9);
  EXPECT_LT(e.py, 1e-9);
}

TEST(FloatingBaseDynamics, OnASlopeTheMomentumRateIsTheRotatedWeight) {
  // Ground frame on a 0.2 rad slope: dp/dt = m g_vec = m g (-sin gamma, -cos gamma) in flight,
  // and K + P with P = -m g_vec . r_com is conserved.
  const FlightErrors e = tumble(dynamics::withSlope(test::fiveLinkRobot(), 0.2));
  RecordProperty("energy_drift_J", fmt::format("{:.2e}", e.energy));
  EXPECT_LT(e.energy, 1e-6);
  EXPECT_LT(e.px, 1e-9);
  EXPECT_LT(e.py, 1e-9);
}

TEST(FloatingBaseDynamics, ChainAtRestFallsAsOneBodyAtG) {
  const Model& m = test::fiveLinkRobot();
  const VecD theta = test::polynomialGait().knots().front().theta;
  const auto fb = dynamics::floatingBaseDynamics(m, theta, VecD::Zero(m.nLinks()));
  Eigen::VectorXd expected = Eigen::VectorXd::Zero(m.nLinks() + 2);
  expected(1) = -m.gravity();
  EXPECT_LT((fb.mass.llt().solve(-fb.bias) - expected).cwiseAbs().maxCoeff(), 1e-12);
  // On a slope the base accelerates at g_vec, the links keep still.
  const Model sloped = dynamics::withSlope(m, -0.15);
  const auto fb_sloped = dynamics::floatingBaseDynamics(sloped, theta, VecD::Zero(m.nLinks()));
  expected.head<2>() = sloped.gravityAcceleration();
  EXPECT_LT((fb_sloped.mass.llt().solve(-fb_sloped.bias) - expected).cwiseAbs().maxCoeff(), 1e-12);
}

}  // namespace
}  // namespace gaitopt::sim
