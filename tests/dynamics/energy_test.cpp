// Free motion with zero torque conserves K + P (DESIGN.md sec. 7, rung 1). Integrated with an
// adaptive 7(8) Runge-Kutta-Fehlberg scheme from Boost.Odeint at tolerance 1e-13.
#include <gtest/gtest.h>

#include <vector>

#include <fmt/format.h>

#include "dynamics/energy.hpp"
#include "dynamics/ssp_dynamics.hpp"
#include "support/fixtures.hpp"
#include "support/chain_simulation.hpp"

namespace gaitopt::test {
namespace {

class EnergyTest : public ::testing::TestWithParam<std::string> {};

TEST_P(EnergyTest, ZeroTorqueFreeMotionConservesEnergyOverTwoSeconds) {
  const auto model = loadNamed(GetParam());
  const int n = model.nLinks();
  std::mt19937 rng(7);
  const VecD th0 = randomPosture(rng, model);
  const VecD dth0 = randomVec(rng, n, -1, 1);
  auto energy = [&](const VecD& th, const VecD& dth) {
    return dynamics::kineticEnergy(model, th, dth) + dynamics::potentialEnergy(model, th);
  };
  const double e0 = energy(th0, dth0);
  double max_drift = 0;
  double max_kinetic = 0;
  simulateSsp(
      model, th0, dth0, [n](double) { return VecD(VecD::Zero(n)); }, evenTimes(2.0, 2000), 1e-13,
      [&](double, const VecD& th, const VecD& dth) {
        max_drift = std::max(max_drift, std::abs(energy(th, dth) - e0));
        max_kinetic = std::max(max_kinetic, dynamics::kineticEnergy(model, th, dth));
      });
  // The motion must be violent enough to test something: the robot falls and flails.
  EXPECT_GT(max_kinetic, 0.2 * std::abs(e0));
  EXPECT_LT(max_drift / std::abs(e0), 1e-8) << "max drift " << max_drift << " J of " << e0;
  RecordProperty("relative_energy_drift", fmt::format("{:.3e}", max_drift / std::abs(e0)));
}

INSTANTIATE_TEST_SUITE_P(AllRobots, EnergyTest, ::testing::ValuesIn(allRobots()));

}  // namespace
}  // namespace gaitopt::test
