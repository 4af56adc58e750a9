// Free motion with zero torque conserves K + P (DESIGN.md sec. 7, rung 1). Integrated with an
// adaptive 7(8) Runge-Kutta-Fehlberg scheme from Boost.Odeint at tolerance 1e-13.
#include <gtest/gtest.h>

#include <boost/numeric/odeint.hpp>
#include <vector>

#include <fmt/format.h>

#include "dynamics/energy.hpp"
#include "dynamics/ssp_dynamics.hpp"
#include "support/fixtures.hpp"

namespace gaitopt::test {
namespace {

using State = std::vector<double>;

double totalEnergy(const dynamics::Model& m, const State& x) {
  const int n = m.nLinks();
  const VecD th = Eigen::Map<const Eigen::VectorXd>(x.data(), n);
  const VecD dth = Eigen::Map<const Eigen::VectorXd>(x.data() + n, n);
  return dynamics::kineticEnergy(m, th, dth) + dynamics::potentialEnergy(m, th);
}

class EnergyTest : public ::testing::TestWithParam<std::string> {};

TEST_P(EnergyTest, ZeroTorqueFreeMotionConservesEnergyOverTwoSeconds) {
  const auto model = loadNamed(GetParam());
  const int n = model.nLinks();
  auto rhs = [&](const State& x, State& dxdt, double) {
    const VecD th = Eigen::Map<const Eigen::VectorXd>(x.data(), n);
    const VecD dth = Eigen::Map<const Eigen::VectorXd>(x.data() + n, n);
    const VecD dd = dynamics::sspForwardDynamics(model, th, dth, VecD::Zero(n));
    for (int i = 0; i < n; ++i) {
      dxdt[static_cast<size_t>(i)] = dth(i);
      dxdt[static_cast<size_t>(n + i)] = dd(i);
    }
  };
  std::mt19937 rng(7);
  const VecD th0 = randomPosture(rng, model);
  const VecD dth0 = randomVec(rng, n, -1, 1);
  State x(th0.data(), th0.data() + n);
  x.insert(x.end(), dth0.data(), dth0.data() + n);
  const double e0 = totalEnergy(model, x);

  namespace ode = boost::numeric::odeint;
  double max_drift = 0;
  double max_kinetic = 0;
  auto observe = [&](const State& s, double) {
    max_drift = std::max(max_drift, std::abs(totalEnergy(model, s) - e0));
    const VecD th = Eigen::Map<const Eigen::VectorXd>(s.data(), n);
    const VecD dth = Eigen::Map<const Eigen::VectorXd>(s.data() + n, n);
    max_kinetic = std::max(max_kinetic, dynamics::kineticEnergy(model, th, dth));
  };
  ode::integrate_adaptive(ode::make_controlled(1e-13, 1e-13, ode::runge_kutta_fehlberg78<State>()),
                          rhs, x, 0.0, 2.0, 1e-3, observe);
  // The motion must be violent enough to test something: the robot falls and flails.
  EXPECT_GT(max_kinetic, 0.2 * std::abs(e0));
  EXPECT_LT(max_drift / std::abs(e0), 1e-8) << "max drift " << max_drift << " J of " << e0;
  RecordProperty("relative_energy_drift", fmt::format("{:.3e}", max_drift / std::abs(e0)));
}

INSTANTIATE_TEST_SUITE_P(AllRobots, EnergyTest, ::testing::ValuesIn(allRobots()));

}  // namespace
}  // namespace gaitopt::test
