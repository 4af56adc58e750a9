// Retiming a step phase by phase (the warm start of a library point at another speed).
#include <cmath>

#include <gtest/gtest.h>

#include "gaits/polynomial/retime.hpp"

namespace gaitopt::test {
namespace {

using gaits::Knot;
using gaits::Phase;

/// theta = sin(t) on two links, SSP on [0, 0.6], DSP on [0.6, 0.7], at `n` knots per phase.
gaits::Trajectory sineStep(int n) {
  std::vector<Knot> knots;
  const auto add = [&](double t, Phase phase) {
    Knot k;
    k.t = t;
    k.phase = phase;
    k.theta = Eigen::VectorXd::Constant(2, std::sin(t));
    k.dtheta = Eigen::VectorXd::Constant(2, std::cos(t));
    k.ddtheta = Eigen::VectorXd::Constant(2, -std::sin(t));
    k.tau = Eigen::VectorXd::Constant(2, t);
    knots.push_back(k);
  };
  for (int i = 0; i <= n; ++i) add(0.6 * i / n, Phase::kSsp);
  for (int i = 0; i <= n; ++i) add(0.6 + 0.1 * i / n, Phase::kDsp);
  return gaits::Trajectory("test", 0.35, knots);
}

TEST(Retimed, StretchesEachPhaseAndScalesTheRates) {
  const gaits::Trajectory step = sineStep(7);
  // Durations whose sums round: the phase switch must stay one instant (no unsorted knots).
  const double ssp = 0.7 / 1.05 * 6 / 7, dsp = 0.7 / 1.05 / 7;
  const gaits::Trajectory r = gaits::retimed(step, {ssp, dsp}, 0.4);
  EXPECT_DOUBLE_EQ(r.stepLength(), 0.4);
  const auto phases = r.phaseDurations();
  ASSERT_EQ(phases.size(), 2u);
  EXPECT_NEAR(phases[0].second, ssp, 1e-15);
  EXPECT_NEAR(phases[1].second, dsp, 1e-15);
  const double c_ssp = ssp / 0.6, c_dsp = dsp / 0.1;
  for (std::size_t k = 0; k < r.knots().size(); ++k) {
    const Knot& a = step.knots()[k];
    const Knot& b = r.knots()[k];
    const double c = a.phase == Phase::kSsp ? c_ssp : c_dsp;
    EXPECT_EQ(a.theta, b.theta);                       // postures kept
    EXPECT_NEAR(b.dtheta(0), a.dtheta(0) / c, 1e-12);  // d/dt' = d/dt / c
    EXPECT_NEAR(b.ddtheta(0), a.ddtheta(0) / (c * c), 1e-12);
    EXPECT_EQ(a.tau, b.tau);
  }
}

TEST(Retimed, RejectsAWrongPhaseCountOrDuration) {
  const gaits::Trajectory step = sineStep(3);
  EXPECT_THROW(gaits::retimed(step, {0.5}, 0.35), std::invalid_argument);
  EXPECT_THROW(gaits::retimed(step, {0.5, 0.0}, 0.35), std::invalid_argument);
}

}  // namespace
}  // namespace gaitopt::test
