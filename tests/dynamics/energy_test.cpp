// Free motion with zero torque conserves K + P (docs/design.md#the-verification-ladder, rung 1), on
// level ground and on a slope. Integrated with an adaptive 7(8) Runge-Kutta-Fehlberg scheme from
// Boost.Odeint at tolerance 1e-13.
#include <gtest/gtest.h>

#include <vector>

#include <fmt/format.h>

#include "dynamics/energy.hpp"
#include "dynamics/model_variation.hpp"
#include "dynamics/ssp_dynamics.hpp"
#include "support/chain_simulation.hpp"
#include "support/fixtures.hpp"

namespace gaitopt::test {
namespace {

class EnergyTest : public ::testing::TestWithParam<std::string> {};

struct EnergyDrift {
  double relative = 0;        ///< max |E(t) - E(0)| / |E(0)| with the model's own P
  double relative_level = 0;  ///< the same with the level-ground P (slope ignored)
};

/// Integrates the zero-torque pinned chain for 2 s and tracks K + P (Mu 2.3-2.4).
EnergyDrift zeroTorqueDrift(const dynamics::Model& model) {
  const int n = model.nLinks();
  const dynamics::Model level = dynamics::withSlope(model, 0.0);
  std::mt19937 rng(7);
  const VecD th0 = randomPosture(rng, model);
  const VecD dth0 = randomVec(rng, n, -1, 1);
  auto energy = [&](const dynamics::Model& m, const VecD& th, const VecD& dth) {
    return dynamics::kineticEnergy(m, th, dth) + dynamics::potentialEnergy(m, th);
  };
  const double e0 = energy(model, th0, dth0), e0_level = energy(level, th0, dth0);
  double max_drift = 0, max_drift_level = 0, max_kinetic = 0;
  simulateSsp(
      model, th0, dth0, [n](double) { return VecD(VecD::Zero(n)); }, evenTimes(2.0, 2000), 1e-13,
      [&](double, const VecD& th, const VecD& dth) {
        max_drift = std::max(max_drift, std::abs(energy(model, th, dth) - e0));
        max_drift_level = std::max(max_drift_level, std::abs(energy(level, th, dth) - e0_level));
        max_kinetic = std::max(max_kinetic, dynamics::kineticEnergy(model, th, dth));
      });
  // The motion must be violent enough to test something: the robot falls and flails.
  EXPECT_GT(max_kinetic, 0.2 * std::abs(e0));
  return {max_drift / std::abs(e0), max_drift_level / std::abs(e0_level)};
}

TEST_P(EnergyTest, ZeroTorqueFreeMotionConservesEnergyOverTwoSeconds) {
  const EnergyDrift drift = zeroTorqueDrift(loadNamed(GetParam()));
  EXPECT_LT(drift.relative, 1e-8);
  RecordProperty("relative_energy_drift", fmt::format("{:.3e}", drift.relative));
}

TEST_P(EnergyTest, OnASlopeZeroTorqueMotionConservesTheRotatedEnergy) {
  // G_i = -g_i sin(theta_i - gamma) is conservative with P = -sum m_i g_vec . r_ci; the level P
  // is not conserved along the same motion, so the check has teeth.
  const EnergyDrift drift = zeroTorqueDrift(dynamics::withSlope(loadNamed(GetParam()), 0.25));
  EXPECT_LT(drift.relative, 1e-8);
  EXPECT_GT(drift.relative_level, 1e-3);
  RecordProperty("relative_energy_drift_on_slope", fmt::format("{:.3e}", drift.relative));
  RecordProperty("relative_drift_of_level_energy", fmt::format("{:.3e}", drift.relative_level));
}

INSTANTIATE_TEST_SUITE_P(AllRobots, EnergyTest, ::testing::ValuesIn(allRobots()));

}  // namespace
}  // namespace gaitopt::test
