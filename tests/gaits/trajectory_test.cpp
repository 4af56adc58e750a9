// Trajectory: validation, quintic Hermite interpolation (exactness and sixth-order convergence),
// right-continuity at the SSP -> DSP switch, resampling at a controller rate.
#include <cmath>
#include <functional>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "gaits/trajectory/trajectory.hpp"
#include "support/same_knots.hpp"

namespace gaitopt::test {
namespace {

using gaits::Knot;
using gaits::Phase;
using gaits::Trajectory;

/// theta, dtheta, ddtheta of every link at time t.
struct Motion {
  std::function<Eigen::VectorXd(double)> theta, dtheta, ddtheta;
};

Knot knotFrom(const Motion& m, double t, Phase phase = Phase::kSsp) {
  Knot k;
  k.t = t;
  k.phase = phase;
  k.theta = m.theta(t);
  k.dtheta = m.dtheta(t);
  k.ddtheta = m.ddtheta(t);
  k.tau = Eigen::VectorXd::Zero(k.theta.size());
  return k;
}

Trajectory sampled(const Motion& m, const std::vector<double>& times) {
  std::vector<Knot> knots;
  for (double t : times) knots.push_back(knotFrom(m, t));
  return Trajectory("test", 0.3, knots);
}

std::vector<double> uniformTimes(double t0, double t1, int intervals) {
  std::vector<double> times;
  for (int k = 0; k <= intervals; ++k) times.push_back(t0 + (t1 - t0) * k / intervals);
  return times;
}

/// A random quintic per link: theta_i(t) = sum_p c(i, p) t^p, and its derivatives.
Motion randomQuintic(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> dist(-2, 2);
  Eigen::MatrixXd c(n, 6);
  for (Eigen::Index i = 0; i < c.size(); ++i) c(i) = dist(rng);
  const auto derivative = [c](int order) {
    return [c, order](double t) {
      Eigen::VectorXd v = Eigen::VectorXd::Zero(c.rows());
      for (int p = order; p < 6; ++p) {
        double factor = 1;
        for (int j = 0; j < order; ++j) factor *= p - j;
        v += c.col(p) * factor * std::pow(t, p - order);
      }
      return v;
    };
  };
  return {derivative(0), derivative(1), derivative(2)};
}

/// theta_i(t) = sin(omega t + phi_i), smooth but not polynomial.
Motion sine(int n) {
  const double omega = 2 * std::numbers::pi;
  const Eigen::ArrayXd phi = Eigen::ArrayXd::LinSpaced(n, 0.0, 1.0);
  return {[=](double t) { return Eigen::VectorXd((omega * t + phi).sin()); },
          [=](double t) { return Eigen::VectorXd(omega * (omega * t + phi).cos()); },
          [=](double t) { return Eigen::VectorXd(-omega * omega * (omega * t + phi).sin()); }};
}

/// Largest interpolation errors of (theta, dtheta, ddtheta) at many off-knot times.
Eigen::Vector3d maxErrors(const Trajectory& traj, const Motion& m) {
  Eigen::Vector3d err = Eigen::Vector3d::Zero();
  const int samples = 997;  // prime, so samples rarely land on knots
  for (int s = 0; s <= samples; ++s) {
    const double t = traj.startTime() + traj.duration() * s / samples;
    const Knot k = traj.at(t);
    err(0) = std::max(err(0), (k.theta - m.theta(t)).cwiseAbs().maxCoeff());
    err(1) = std::max(err(1), (k.dtheta - m.dtheta(t)).cwiseAbs().maxCoeff());
    err(2) = std::max(err(2), (k.ddtheta - m.ddtheta(t)).cwiseAbs().maxCoeff());
  }
  return err;
}

/// A two-link step: SSP knots at 0, 0.3, 0.6 and DSP knots at 0.6, 0.7, with jumps at 0.6.
Trajectory stepWithSwitch(double t_switch = 0.6, double t_end = 0.7) {
  std::vector<Knot> knots;
  const auto add = [&](double t, Phase phase, double value) {
    Knot k;
    k.t = t;
    k.phase = phase;
    k.theta = Eigen::Vector2d(value, -value);
    k.dtheta = Eigen::Vector2d(2 * value, 1);
    k.ddtheta = Eigen::Vector2d(-value, 3);
    k.tau = Eigen::Vector2d(10 * value, -5);
    k.force_stance = Eigen::Vector2d(1, 100 + value);
    k.force_swing = phase == Phase::kDsp ? Eigen::Vector2d(-1, 50) : Eigen::Vector2d::Zero();
    knots.push_back(k);
  };
  add(0.0, Phase::kSsp, 0.1);
  add(0.5 * t_switch, Phase::kSsp, 0.2);
  add(t_switch, Phase::kSsp, 0.3);
  add(t_switch, Phase::kDsp, 0.4);  // rates, torques and forces jump at touchdown
  add(t_end, Phase::kDsp, 0.5);
  return Trajectory("test", 0.3, knots);
}

/// Expects the constructor to throw std::invalid_argument with `text` in its message.
void expectRejected(std::vector<Knot> knots, const std::string& text) {
  try {
    Trajectory("test", 0.3, std::move(knots));
    ADD_FAILURE() << "expected std::invalid_argument containing '" << text << "'";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(text), std::string::npos) << e.what();
  }
}

// --- interpolation --------------------------------------------------------------------------

TEST(TrajectoryInterpolation, QuinticHermiteReproducesAQuinticExactly) {
  const Motion m = randomQuintic(5, 11);
  const Trajectory traj = sampled(m, {0.0, 0.13, 0.3, 0.52, 0.7});  // uneven spacing
  const Eigen::Vector3d err = maxErrors(traj, m);
  EXPECT_LT(err(0), 1e-10);
  EXPECT_LT(err(1), 1e-10);
  EXPECT_LT(err(2), 1e-10);
}

TEST(TrajectoryInterpolation, SineConvergesAtSixthOrder) {
  const Motion m = sine(3);
  const Eigen::Vector3d coarse = maxErrors(sampled(m, uniformTimes(0, 1, 10)), m);
  const Eigen::Vector3d fine = maxErrors(sampled(m, uniformTimes(0, 1, 20)), m);
  const Eigen::Vector3d order = (coarse.array() / fine.array()).log() / std::log(2.0);
  // Measured 5.99, 4.99, 3.99.
  EXPECT_GT(order(0), 5.5) << "theta: quintic Hermite is O(h^6)";
  EXPECT_GT(order(1), 4.5) << "dtheta: O(h^5)";
  EXPECT_GT(order(2), 3.5) << "ddtheta: O(h^4)";
  EXPECT_LT(coarse(0), 1e-5);  // the errors measured are interpolation, not rounding
  EXPECT_GT(fine(0), 1e-12);
}

TEST(TrajectoryInterpolation, TorqueAndForcesAreLinearAndExactForLinearData) {
  std::vector<Knot> knots;
  for (double t : {0.0, 0.2, 0.45, 0.7}) {
    Knot k;
    k.t = t;
    k.theta = k.dtheta = k.ddtheta = Eigen::Vector3d::Zero();
    k.tau = Eigen::Vector3d(1 + 2 * t, -3 * t, 0.5);
    k.force_stance = Eigen::Vector2d(4 * t, 200 - 10 * t);
    knots.push_back(k);
  }
  const Trajectory traj("test", 0.3, knots);
  for (double t : {0.05, 0.31, 0.449, 0.6999}) {
    const Knot k = traj.at(t);
    EXPECT_NEAR(k.tau(0), 1 + 2 * t, 1e-13);
    EXPECT_NEAR(k.tau(1), -3 * t, 1e-13);
    EXPECT_NEAR(k.tau(2), 0.5, 1e-13);
    EXPECT_NEAR(k.force_stance(0), 4 * t, 1e-13);
    EXPECT_NEAR(k.force_stance(1), 200 - 10 * t, 1e-12);
    EXPECT_EQ(k.t, t);
  }
}

TEST(TrajectoryInterpolation, KnotTimesReturnTheKnotsExactly) {
  const Trajectory traj = sampled(sine(2), uniformTimes(0, 1, 7));
  for (const Knot& k : traj.knots()) expectSameKnot(traj.at(k.t), k);
}

// --- phase switch and range ------------------------------------------------------------------

TEST(TrajectorySwitch, EvaluationIsRightContinuousAtTheSwitch) {
  const Trajectory traj = stepWithSwitch();
  const Knot& ssp = traj.knots()[2];
  const Knot& dsp = traj.knots()[3];
  expectSameKnot(traj.at(0.6), dsp);
  // Approaching from the left gives the SSP knot's values, not the DSP ones.
  const Knot before = traj.at(std::nextafter(0.6, 0.0));
  EXPECT_EQ(before.phase, Phase::kSsp);
  EXPECT_NEAR((before.dtheta - ssp.dtheta).norm(), 0, 1e-9);
  EXPECT_NEAR((before.tau - ssp.tau).norm(), 0, 1e-9);
  const Knot after = traj.at(0.6 + 1e-12);
  EXPECT_EQ(after.phase, Phase::kDsp);
  EXPECT_NEAR((after.dtheta - dsp.dtheta).norm(), 0, 1e-9);
}

TEST(TrajectorySwitch, EndTimeReturnsTheLastKnot) {
  const Trajectory traj = stepWithSwitch();
  expectSameKnot(traj.at(0.7), traj.knots().back());
  // A switch exactly at the end (zero-length DSP): the final DSP knot is returned.
  auto knots = traj.knots();
  knots.pop_back();
  expectSameKnot(Trajectory("test", 0.3, knots).at(0.6), knots.back());
}

TEST(TrajectorySwitch, AtThrowsOutsideTheStep) {
  const Trajectory traj = stepWithSwitch();
  EXPECT_THROW(traj.at(-1e-12), std::out_of_range);
  EXPECT_THROW(traj.at(0.7 + 1e-12), std::out_of_range);
  EXPECT_THROW(traj.at(std::nan("")), std::out_of_range);
  EXPECT_THROW(Trajectory().at(0.0), std::out_of_range);
}

TEST(TrajectorySwitch, PhaseDurationsInOrder) {
  const auto phases = stepWithSwitch().phaseDurations();
  ASSERT_EQ(phases.size(), 2u);
  EXPECT_EQ(phases[0].first, Phase::kSsp);
  EXPECT_DOUBLE_EQ(phases[0].second, 0.6);
  EXPECT_EQ(phases[1].first, Phase::kDsp);
  EXPECT_NEAR(phases[1].second, 0.1, 1e-15);
  EXPECT_TRUE(Trajectory().phaseDurations().empty());
}

TEST(TrajectorySwitch, PhaseNamesRoundTrip) {
  EXPECT_STREQ(gaits::toString(Phase::kSsp), "SSP");
  EXPECT_STREQ(gaits::toString(Phase::kDsp), "DSP");
  EXPECT_EQ(gaits::phaseFromString("SSP"), Phase::kSsp);
  EXPECT_EQ(gaits::phaseFromString("DSP"), Phase::kDsp);
  EXPECT_THROW(gaits::phaseFromString("ssp"), std::invalid_argument);
}

// --- validation ------------------------------------------------------------------------------

TEST(TrajectoryValidation, RejectsUnsortedKnots) {
  auto knots = stepWithSwitch().knots();
  std::swap(knots[0].t, knots[1].t);
  expectRejected(knots, "knot 1: time 0 is before knot 0's 0.3");
}

TEST(TrajectoryValidation, RejectsNonFiniteValues) {
  auto knots = stepWithSwitch().knots();
  knots[4].dtheta(1) = std::nan("");
  expectRejected(knots, "knot 4: dtheta[1] is nan");
  knots = stepWithSwitch().knots();
  knots[1].force_swing(0) = INFINITY;
  expectRejected(knots, "knot 1: force_swing[0] is inf");
  knots = stepWithSwitch().knots();
  knots[2].t = std::nan("");
  expectRejected(knots, "knot 2: time is nan");
}

TEST(TrajectoryValidation, RejectsMismatchedSizes) {
  auto knots = stepWithSwitch().knots();
  knots[3].tau = Eigen::Vector3d::Zero();
  expectRejected(knots, "knot 3: tau has 3 entries, expected 2");
  knots = stepWithSwitch().knots();
  knots[0].ddtheta.resize(0);
  expectRejected(knots, "knot 0: ddtheta has 0 entries, expected 2");
  expectRejected({}, "at least one knot");
}

TEST(TrajectoryValidation, RejectsDspToSspAtTheSameTime) {
  auto knots = stepWithSwitch().knots();
  for (size_t k = 0; k < knots.size(); ++k) knots[k].phase = k < 3 ? Phase::kDsp : Phase::kSsp;
  expectRejected(knots, "knots 2 and 3 share the time 0.6 but are DSP -> SSP");
}

TEST(TrajectoryValidation, RejectsAPhaseChangeWithoutASwitchPair) {
  auto knots = stepWithSwitch().knots();
  knots.erase(knots.begin() + 2);  // SSP at 0.3, DSP at 0.6: the switch time is unknown
  expectRejected(knots, "knots 1 and 2 change phase SSP -> DSP");
}

TEST(TrajectoryValidation, RejectsThreeKnotsAtTheSameTime) {
  auto knots = stepWithSwitch().knots();
  const Knot extra = knots[3];
  knots.insert(knots.begin() + 3, extra);
  expectRejected(knots, "knots 3 and 4 share the time 0.6 but are DSP -> DSP");
}

// --- resampling ------------------------------------------------------------------------------

/// Resampling contract: starts and ends on the original knots, keeps the switch pair exactly,
/// and every other sample is the interpolant on the rate grid.
void checkResampled(const Trajectory& traj, const Trajectory& r, double rate) {
  expectSameKnot(r.knots().front(), traj.knots().front());
  expectSameKnot(r.knots().back(), traj.knots().back());
  int pairs = 0;
  for (size_t k = 0; k < r.knots().size(); ++k) {
    const Knot& knot = r.knots()[k];
    if (k + 1 < r.knots().size() && knot.t == r.knots()[k + 1].t) {
      expectSameKnot(knot, traj.knots()[2]);
      expectSameKnot(r.knots()[k + 1], traj.knots()[3]);
      ++pairs;
      continue;
    }
    if (k + 1 == r.knots().size() || (k > 0 && knot.t == r.knots()[k - 1].t)) continue;
    const double steps = (knot.t - traj.startTime()) * rate;
    EXPECT_NEAR(steps, std::round(steps), 1e-6) << "sample " << k << " is off the grid";
    expectSameKnot(knot, traj.at(knot.t));
  }
  EXPECT_EQ(pairs, 1);
}

TEST(TrajectoryResample, OneKilohertzKeepsOffGridSwitchAndEnd) {
  const Trajectory traj = stepWithSwitch(0.6005, 0.7003);
  const Trajectory r = traj.resample(1000);
  // Grid 0, 1 ms, ..., 700 ms (701 samples), the switch pair, the end knot.
  EXPECT_EQ(r.knots().size(), 701u + 2u + 1u);
  checkResampled(traj, r, 1000);
  EXPECT_EQ(r.phaseDurations().size(), 2u);
  EXPECT_EQ(r.robot(), traj.robot());
  EXPECT_EQ(r.stepLength(), traj.stepLength());
}

TEST(TrajectoryResample, OnGridSwitchAndEndAreNotDuplicated) {
  const Trajectory traj = stepWithSwitch(0.6, 0.7);
  const Trajectory r = traj.resample(1000);
  // 0..599 ms (600 samples), the pair at 600 ms replacing its grid point, 601..700 ms (100).
  EXPECT_EQ(r.knots().size(), 600u + 2u + 100u);
  checkResampled(traj, r, 1000);
  EXPECT_EQ(r.knots()[600].t, 0.6);
}

TEST(TrajectoryResample, EndWithinToleranceOfTheGridIsNotASliver) {
  const Trajectory traj = stepWithSwitch(0.6, 0.7 + 5e-10);
  const Trajectory r = traj.resample(1000);
  EXPECT_EQ(r.knots().size(), 702u);
  EXPECT_GT(r.knots()[r.knots().size() - 1].t - r.knots()[r.knots().size() - 2].t, 0.9e-3);
}

TEST(TrajectoryResample, RejectsNonPositiveRate) {
  EXPECT_THROW(stepWithSwitch().resample(0), std::invalid_argument);
  EXPECT_THROW(stepWithSwitch().resample(-5), std::invalid_argument);
  EXPECT_THROW(stepWithSwitch().resample(std::nan("")), std::invalid_argument);
}

}  // namespace
}  // namespace gaitopt::test
