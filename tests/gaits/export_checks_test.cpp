// Checks on a dense export (gaits/export/export_checks.hpp) against trajectories whose answers are
// known in closed form.
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "dynamics/kinematics.hpp"
#include "gaits/export/export_checks.hpp"
#include "support/fixtures.hpp"

namespace gaitopt::test {
namespace {

using gaits::Knot;
using gaits::Phase;
using gaits::Trajectory;

/// theta_i = a_i sin(omega t) sampled at `rate` Hz over one SSP of 0.6 s, with the rates
/// scaled by `rate_scale` and the accelerations by `acceleration_scale` (1: exact derivatives).
Trajectory sineStep(double rate, double rate_scale, double acceleration_scale = 1.0) {
  const int n = 5;
  const double omega = 7.0;
  std::vector<Knot> knots;
  for (int j = 0; j <= static_cast<int>(0.6 * rate); ++j) {
    Knot k;
    k.t = j / rate;
    const Eigen::VectorXd amp = Eigen::VectorXd::LinSpaced(n, 0.1, 0.5);
    k.theta = amp * std::sin(omega * k.t);
    k.dtheta = rate_scale * omega * amp * std::cos(omega * k.t);
    k.ddtheta = -acceleration_scale * omega * omega * k.theta;
    k.tau = Eigen::VectorXd::Zero(n);
    k.force_stance = Eigen::Vector2d(0, 200);
    knots.push_back(k);
  }
  return Trajectory("test", 0.35, knots);
}

TEST(ExportChecks, RatesThatAreTheDerivativeOfTheAnglesShowNoMismatch) {
  // Three-point differences err by h^2 omega^2 / 6 relative: 8e-6 at 1 kHz.
  EXPECT_LT(gaits::maxRateMismatch(sineStep(1000, 1.0)), 2e-5);
  // Rates 1 % too large are seen as 1 % off, whatever the sample rate.
  EXPECT_NEAR(gaits::maxRateMismatch(sineStep(1000, 1.01)), 0.01 / 1.01, 1e-4);
  EXPECT_NEAR(gaits::maxRateMismatch(sineStep(200, 1.01)), 0.01 / 1.01, 1e-3);
}

TEST(ExportChecks, AccelerationsThatAreTheDerivativeOfTheRatesShowNoMismatch) {
  EXPECT_LT(gaits::maxAccelerationMismatch(sineStep(1000, 1.0)), 2e-5);
  // Accelerations 2 % too large are seen as 2 % off; the rates' own check does not see them.
  EXPECT_NEAR(gaits::maxAccelerationMismatch(sineStep(1000, 1.0, 1.02)), 0.02 / 1.02, 1e-4);
  EXPECT_LT(gaits::maxRateMismatch(sineStep(1000, 1.0, 1.02)), 2e-5);
}

TEST(ExportChecks, FootCentreOfPressureIsMinusTheAnkleTorqueOverTheNormalForce) {
  const dynamics::Model model = loadNamed("mu2004_five_link");
  const double heel = model.foot().heel, toe = model.foot().toe;
  Trajectory traj = sineStep(100, 1.0);
  std::vector<Knot> knots = traj.knots();
  knots[3].tau(0) = -0.5 * toe * 200;  // CoP at toe / 2: margin toe / 2
  knots[5].tau(0) = 1.2 * heel * 200;  // CoP 0.2 heel behind the heel: margin -0.2 heel
  EXPECT_NEAR(gaits::minFootCopMargin(Trajectory("test", 0.35, knots), model), -0.2 * heel, 1e-12);
  knots[5].force_stance.y() = 0;  // an unloaded foot carries no torque
  EXPECT_EQ(gaits::minFootCopMargin(Trajectory("test", 0.35, knots), model),
            -std::numeric_limits<double>::infinity());
}

TEST(ExportChecks, ClearanceAndDriftAreTheSwingTipsHeightAndDistanceFromItsPin) {
  const dynamics::Model model = loadNamed("mu2004_five_link");
  const Trajectory traj = sineStep(100, 1.0);
  double lowest = 1e9;
  for (const auto& k : traj.knots())
    lowest = std::min(lowest, dynamics::swingTip(model, VecD(k.theta)).y());
  EXPECT_DOUBLE_EQ(gaits::minSwingClearance(traj, model), lowest);
  EXPECT_EQ(gaits::maxDspTipDrift(traj, model), 0.0);  // no DSP knot
  std::vector<Knot> knots = traj.knots();
  Knot dsp = knots.back();
  dsp.phase = Phase::kDsp;
  knots.push_back(dsp);
  const Vec2d tip = dynamics::swingTip(model, VecD(dsp.theta));
  const double step = tip.x() + 0.003;  // E 3 mm short of where it was pinned, and off the ground
  EXPECT_NEAR(gaits::maxDspTipDrift(Trajectory("test", step, knots), model),
              std::hypot(0.003, tip.y()), 1e-12);
}

}  // namespace
}  // namespace gaitopt::test
