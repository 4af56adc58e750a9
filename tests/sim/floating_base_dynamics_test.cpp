// The free-base equations of motion the compliant and LCP walks integrate
// (dynamics/floating_base_dynamics.hpp): without contact and torque they conserve energy and
// horizontal momentum, the vertical momentum falls at m g, and a chain at rest falls as a rigid
// body at g.
#include <gtest/gtest.h>

#include <fmt/format.h>
#include <Eigen/Cholesky>

#include "dynamics/energy.hpp"
#include "dynamics/floating_base_dynamics.hpp"
#include "five_link_gait.hpp"
#include "sim/event_integrator.hpp"

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
         dynamics::potentialEnergy<double>(m, theta) + m.totalMass() * m.gravity() * x(1);
}

Vec2d momentum(const Model& m, const Eigen::VectorXd& x) {
  const int n = m.nLinks();
  return dynamics::linearMomentum<double>(m, VecD(x.segment(2, n)), VecD(x.tail(n)),
                                          Vec2d(x.segment<2>(n + 2)));
}

TEST(FloatingBaseDynamics, FreeChainConservesEnergyAndFallsWithItsWeight) {
  const Model& m = test::fiveLinkRobot();
  const int n = m.nLinks();
  Eigen::VectorXd x(2 * (n + 2));
  // A tumbling robot: base moving up and forward, every link turning (rad/s).
  x << 0.1, 0.8, 0.1, 0.3, -0.05, 3.0, 2.9,  //
      0.5, 1.5, -1.0, 2.0, 0.5, -3.0, 4.0;
  const double e0 = energy(m, x);
  const Vec2d p0 = momentum(m, x);
  const double h = 1e-3, duration = 1.0;
  double worst_energy = 0, worst_px = 0, worst_py = 0;
  const Rhs f = [&](double, const Eigen::VectorXd& s) { return freeFlight(m, s); };
  for (int k = 1; k * h <= duration + 1e-12; ++k) {
    x = rk4Step(f, 0.0, x, h);
    const Vec2d p = momentum(m, x);
    worst_energy = std::max(worst_energy, std::abs(energy(m, x) - e0));
    worst_px = std::max(worst_px, std::abs(p(0) - p0(0)));
    worst_py = std::max(worst_py, std::abs(p(1) - (p0(1) - m.totalMass() * m.gravity() * k * h)));
  }
  RecordProperty("energy_drift_J", fmt::format("{:.2e}", worst_energy));
  // RK4 at 1 ms: the drift is O(h^4); 1e-6 J against kinetic energies of ~100 J.
  EXPECT_LT(worst_energy, 1e-6);
  // Momentum is linear in the state's velocities and its rate is exact in the dynamics, so RK4
  // keeps it to rounding.
  EXPECT_LT(worst_px, 1e-9);
  EXPECT_LT(worst_py, 1e-9);
}

TEST(FloatingBaseDynamics, ChainAtRestFallsAsOneBodyAtG) {
  const Model& m = test::fiveLinkRobot();
  const VecD theta = test::polynomialGait().knots().front().theta;
  const auto fb = dynamics::floatingBaseDynamics(m, theta, VecD::Zero(m.nLinks()));
  Eigen::VectorXd expected = Eigen::VectorXd::Zero(m.nLinks() + 2);
  expected(1) = -m.gravity();
  EXPECT_LT((fb.mass.llt().solve(-fb.bias) - expected).cwiseAbs().maxCoeff(), 1e-12);
}

}  // namespace
}  // namespace gaitopt::sim
