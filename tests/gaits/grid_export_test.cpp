// The fixed-rate export (gaits/trajectory/grid_export.hpp): samples exactly on t_i = i / rate with
// time strictly increasing, each in the phase it lies in, and the switch pair and the end kept so
// the step is rebuilt knot for knot.
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "config/config_error.hpp"
#include "gaits/trajectory/grid_export.hpp"
#include "support/same_knots.hpp"

namespace gaitopt::test {
namespace {

using gaits::Knot;
using gaits::Phase;
using gaits::Trajectory;

/// A smooth five-link step (not physical) with knots every `h` seconds, the SSP -> DSP switch at
/// `t_switch` and the end at `t_end`; rates and forces jump at the switch as at an impact.
Trajectory stepWithSwitch(double h, double t_switch, double t_end) {
  const Eigen::ArrayXd phase = Eigen::ArrayXd::LinSpaced(5, 0.0, 1.0);
  std::vector<Knot> knots;
  const auto add = [&](double t, Phase p) {
    const double jump = p == Phase::kDsp ? 0.2 : 0.0;
    Knot k;
    k.t = t;
    k.phase = p;
    k.theta = 0.3 * (3 * t + phase).sin();
    k.dtheta = 0.9 * (3 * t + phase).cos() - jump;
    k.ddtheta = -2.7 * (3 * t + phase).sin() + jump;
    k.tau = 20 * (t + phase).sin() + jump;
    k.force_stance = Eigen::Vector2d(3 + t, 250 - 100 * t);
    if (p == Phase::kDsp) k.force_swing = Eigen::Vector2d(-2.7, 90);
    knots.push_back(k);
  };
  const auto grid = [h](int k) { return k * h; };
  for (int k = 0; grid(k) < t_switch - 1e-9; ++k) add(grid(k), Phase::kSsp);
  add(t_switch, Phase::kSsp);
  add(t_switch, Phase::kDsp);
  for (int k = 1; grid(k) < t_end - 1e-9; ++k)
    if (grid(k) > t_switch + 1e-9) add(grid(k), Phase::kDsp);
  add(t_end, Phase::kDsp);
  return Trajectory("synthetic", 0.35, knots);
}

TEST(GridExport, SamplesLieOnOneGridWithTimeStrictlyIncreasing) {
  // Free phase durations: neither the switch (0.6137 s) nor the end (0.7213 s) is on the grid.
  const Trajectory step = stepWithSwitch(0.01, 0.6137, 0.7213);
  const gaits::GridExport grid = gaits::exportGrid(step, 1000);
  ASSERT_EQ(grid.samples.size(), 722u);  // i = 0..721, 0.721 <= 0.7213 < 0.722
  for (size_t i = 0; i < grid.samples.size(); ++i) {
    const Knot& s = grid.samples[i];
    EXPECT_NEAR(s.t, static_cast<double>(i) / 1000, 1e-12) << i;
    if (i > 0) {
      EXPECT_GT(s.t, grid.samples[i - 1].t) << i;
    }
    EXPECT_EQ(s.phase, s.t < 0.6137 ? Phase::kSsp : Phase::kDsp) << i;
  }
  // The switch falls inside the interval (0.613, 0.614]; its two states are kept beside.
  EXPECT_EQ(grid.samples[613].phase, Phase::kSsp);
  EXPECT_EQ(grid.samples[614].phase, Phase::kDsp);
  ASSERT_EQ(grid.switches.size(), 1u);
  expectSameKnot(grid.switches[0].before, step.knots()[62], 62);  // the last SSP knot
  expectSameKnot(grid.switches[0].after, step.knots()[63], 63);
  expectSameKnot(grid.end, step.knots().back(), 0);
  EXPECT_EQ(grid.end.t, 0.7213);  // the period, off the grid, is kept
}

TEST(GridExport, JoiningTheGridGivesTheStepResampledAtTheRate) {
  // Nothing is lost: the grid with its switch states is the old export (resample) knot for knot.
  const Trajectory step = stepWithSwitch(0.01, 0.6137, 0.7213);
  for (double rate : {1000.0, 333.0, 50.0}) {
    const gaits::GridExport grid = gaits::exportGrid(step, rate);
    const Trajectory joined =
        gaits::joinGrid(step.robot(), step.stepLength(), grid.samples, grid.switches, grid.end);
    expectSameKnots(joined, step.resample(rate));
    EXPECT_EQ(joined.phaseDurations(), step.phaseDurations());
  }
}

TEST(GridExport, ASampleAtTheSwitchIsThePostSwitchState) {
  // Fixed durations on the grid: the sample at the switch time is the DSP's first knot (at() is
  // right-continuous), the sample at the end is the end knot; joined, neither is doubled.
  const Trajectory step = stepWithSwitch(0.025, 0.6, 0.7);
  const gaits::GridExport grid = gaits::exportGrid(step, 20);
  ASSERT_EQ(grid.samples.size(), 15u);
  EXPECT_EQ(grid.samples[12].t, 0.6);
  expectSameKnot(grid.samples[12], grid.switches.at(0).after, 12);
  expectSameKnot(grid.samples[14], grid.end, 14);
  const Trajectory joined =
      gaits::joinGrid(step.robot(), step.stepLength(), grid.samples, grid.switches, grid.end);
  ASSERT_EQ(joined.knots().size(), 16u);  // 0 .. 0.55, the pair at 0.6, 0.65, the end at 0.7
  expectSameKnot(joined.knots()[12], grid.switches[0].before, 12);
  expectSameKnot(joined.knots()[13], grid.switches[0].after, 13);
  expectSameKnot(joined.knots()[14], grid.samples[13], 14);
  expectSameKnot(joined.knots()[15], grid.end, 15);
}

TEST(GridExport, RejectsABadRateAndAStepNotStartingAtZero) {
  const Trajectory step = stepWithSwitch(0.01, 0.6137, 0.7213);
  EXPECT_THROW(gaits::exportGrid(step, 0), std::invalid_argument);
  EXPECT_THROW(gaits::exportGrid(step, std::nan("")), std::invalid_argument);
  std::vector<Knot> late = step.knots();
  for (Knot& k : late) k.t += 0.5;
  EXPECT_THROW(gaits::exportGrid(Trajectory("late", 0.35, late), 1000), std::invalid_argument);
}

TEST(GridExport, ARateThatSamplesTheStepTooFewTimesIsBadInput) {
  // 0.7213 s: 9 samples at 12 Hz (i = 0..8), 10 at 13 Hz, the rate the message asks for.
  const Trajectory step = stepWithSwitch(0.01, 0.6137, 0.7213);
  try {
    gaits::exportGrid(step, 12);
    FAIL() << "9 samples were exported";
  } catch (const config::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("12 Hz samples the 0.7213 s step 9 time(s), fewer than "
                                         "the 10 an export needs: use 13 Hz or more"),
              std::string::npos)
        << e.what();
  }
  EXPECT_EQ(gaits::exportGrid(step, 13).samples.size(), gaits::kMinExportSamples);
}

}  // namespace
}  // namespace gaitopt::test
