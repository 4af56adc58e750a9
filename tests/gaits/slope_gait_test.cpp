// The polynomial gait of Mu ch. 3 on a slope: designed in the ground frame with gravity
// rotated (dynamics/model.hpp), its torques drive the sloped chain along it in a forward
// simulation, and its energy balance is the physics of walking uphill: over one step the net
// actuator work equals the potential gained, m g step_length sin(gamma), since the gait is periodic
// and touches down without impact (kinetic energy change 0). Also the `slope` key of the gait file.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include <fmt/format.h>

#include "config/config_error.hpp"
#include "dynamics/energy.hpp"
#include "dynamics/joint_coordinates.hpp"
#include "dynamics/model_variation.hpp"
#include "gaits/export/consistency.hpp"
#include "gaits/export/metrics.hpp"
#include "gaits/polynomial/hip_plan_search.hpp"
#include "support/chain_simulation.hpp"
#include "support/fixtures.hpp"

namespace gaitopt::test {
namespace {

const std::string kGait = std::string(GAITOPT_SOURCE_DIR) + "/configs/gaits/mu2004.yaml";

/// Net actuator work over the step, the integral of sum_j tau_j dq_j (trapezoid over the knots;
/// q = M theta, Mu 2.41) [J].
double netWork(const gaits::Trajectory& traj) {
  const auto& knots = traj.knots();
  auto power = [](const gaits::Knot& k) { return k.tau.dot(dynamics::toJoint(VecD(k.dtheta))); };
  double w = 0;
  for (size_t k = 0; k + 1 < knots.size(); ++k)
    w += 0.5 * (power(knots[k]) + power(knots[k + 1])) * (knots[k + 1].t - knots[k].t);
  return w;
}

class PolynomialGaitOnASlope : public ::testing::Test {
 protected:
  static constexpr double kGamma = 0.1;  // uphill [rad]
  static void SetUpTestSuite() {
    model_ = new dynamics::Model(dynamics::withSlope(loadNamed("mu2004_five_link"), kGamma));
    gaits::GaitParams params = gaits::loadGait(kGait);
    params.slope = kGamma;
    const gaits::HipPlanSearch search = gaits::searchHipPlan(*model_, params);
    traj_ = new gaits::Trajectory(
        gaits::buildTrajectory(gaits::PolynomialGait(*model_, params, search.plan), *model_, 1000));
  }
  static void TearDownTestSuite() {
    delete traj_;
    delete model_;
  }
  /// m g sin(gamma): the weight's component down the slope [N].
  static double weightAlongSlope() {
    return model_->totalMass() * model_->gravity() * std::sin(kGamma);
  }
  static dynamics::Model* model_;
  static gaits::Trajectory* traj_;
};
dynamics::Model* PolynomialGaitOnASlope::model_ = nullptr;
gaits::Trajectory* PolynomialGaitOnASlope::traj_ = nullptr;

/// Largest angle error of the chain integrated under the trajectory's torques (linear between
/// the 1 kHz samples) over one phase, pinned at B (SSP) or at both tips (DSP), from the phase's
/// first state [rad].
double resimulatedPhaseError(const dynamics::Model& m, const gaits::Trajectory& traj, bool dsp,
                             double start, double end) {
  const gaits::Knot k0 = traj.at(start);
  const double last = std::nextafter(end, start);  // this phase's side of a switch
  const auto at = [&](double t) { return traj.at(std::min(start + t, last)); };
  double worst = 0;
  simulateChain(
      m, dsp, k0.theta, k0.dtheta, [&](double t) { return VecD(at(t).tau); },
      evenTimes(end - start, 100), 1e-10,
      [&](double t, const VecD& theta, const VecD&) {
        worst = std::max(worst, (theta - at(t).theta).cwiseAbs().maxCoeff());
      });
  return worst;
}

TEST_F(PolynomialGaitOnASlope, TorquesReproduceTheStepByForwardSimulation) {
  // Forward dynamics on the sloped model (D ddtheta + N = M^T tau, Mu 2.7, and the KKT solve of
  // the DSP, 2.11) from each phase's first state: the torques of the gait drive it along the
  // gait, with gravity rotated.
  const auto phases = traj_->phaseDurations();
  ASSERT_EQ(phases.size(), 2u);
  const double t0 = traj_->startTime(), t_s = t0 + phases[0].second;
  const double ssp = resimulatedPhaseError(*model_, *traj_, false, t0, t_s);
  const double dsp = resimulatedPhaseError(*model_, *traj_, true, t_s, traj_->endTime());
  RecordProperty("ssp_resimulation_max_angle_error_rad", fmt::format("{:.3e}", ssp));
  RecordProperty("dsp_resimulation_max_angle_error_rad", fmt::format("{:.3e}", dsp));
  // The torques' interpolation error (linear between the samples), O(h^2): measured 3.1e-4 rad
  // over the 0.6 s SSP, which amplifies it, and 1.2e-6 rad over the 0.1 s DSP (1.4e-3 and
  // 4.8e-6 at 500 Hz); the bounds are about 3 and 4 times the 1 kHz values.
  EXPECT_LT(ssp, 1e-3);
  EXPECT_LT(dsp, 5e-6);
}

TEST_F(PolynomialGaitOnASlope, NetWorkEqualsThePotentialGained) {
  // Impactless and periodic: the kinetic energy does not change over the step.
  EXPECT_LT(gaits::touchdownVelocityJump(*traj_, *model_), 1e-9);
  EXPECT_LT(gaits::periodicityError(*traj_, *model_), 1e-9);
  const auto& first = traj_->knots().front();
  const auto& last = traj_->knots().back();
  const double dk = dynamics::kineticEnergy<double>(*model_, last.theta, last.dtheta) -
                    dynamics::kineticEnergy<double>(*model_, first.theta, first.dtheta);

  const double lift = weightAlongSlope() * traj_->stepLength();
  const double work = netWork(*traj_);
  const double err = std::abs(work - (lift + dk)) / lift;
  RecordProperty("net_work_J", fmt::format("{:.4f}", work));
  RecordProperty("potential_gain_J", fmt::format("{:.4f}", lift));
  RecordProperty("kinetic_change_J", fmt::format("{:.2e}", dk));
  RecordProperty("relative_balance_error", fmt::format("{:.2e}", err));
  EXPECT_LT(std::abs(dk), 1e-6 * lift);
  // The work is a trapezoid over the 1 kHz samples, O(h^2): measured 1.0e-5 of the 10.2 J
  // (4.0e-5 at 500 Hz), the bound is 3 times that.
  EXPECT_LT(err, 3e-5);
}

TEST_F(PolynomialGaitOnASlope, MeanTangentialForceIsTheWeightAlongTheSlope) {
  // Uphill the ground pushes the robot up the slope on average: the mean tangential force equals
  // m g sin(gamma) (momentum over a periodic step), so the stance force points uphill.
  double impulse_x = 0;
  const auto& knots = traj_->knots();
  for (size_t k = 0; k + 1 < knots.size(); ++k) {
    auto fx = [](const gaits::Knot& q) { return q.force_stance(0) + q.force_swing(0); };
    impulse_x += 0.5 * (fx(knots[k]) + fx(knots[k + 1])) * (knots[k + 1].t - knots[k].t);
  }
  const double mean = impulse_x / traj_->duration();
  RecordProperty("mean_tangential_force_N", fmt::format("{:.3f}", mean));
  // Trapezoid at 1 kHz as the work: measured 7.1e-6 of the 29.2 N, the bound is 3 times that.
  EXPECT_NEAR(mean, weightAlongSlope(), 2e-5 * weightAlongSlope());
}

/// The ConfigError message of loading the shipped gait with `line` appended, or "no error".
std::string gaitError(const std::string& line) {
  const auto path =
      std::filesystem::temp_directory_path() / fmt::format("gaitopt_slope_{}.yaml", ::getpid());
  {
    std::ifstream in(kGait);
    std::ofstream out(path);
    out << in.rdbuf() << '\n' << line << '\n';
  }
  std::string message = "no error";
  try {
    const gaits::GaitParams p = gaits::loadGait(path.string());
    message = fmt::format("no error, slope {}", p.slope);
  } catch (const config::ConfigError& e) {
    message = e.what();
  }
  std::filesystem::remove(path);
  return message;
}

TEST(GaitConfigSlope, DefaultsToLevelAndRejectsDegreesAndSteepSlopes) {
  EXPECT_EQ(gaits::loadGait(kGait).slope, 0.0);
  EXPECT_EQ(gaitError("slope: -0.1"), "no error, slope -0.1");
  const std::string degrees = gaitError("slope: 5");
  EXPECT_NE(degrees.find("key 'slope': expected an angle in [-0.35, 0.35] [rad] (degrees? 5 deg "
                         "is 0.08727 rad), got 5"),
            std::string::npos)
      << degrees;
  const std::string steep = gaitError("slope: 30");
  EXPECT_NE(steep.find("key 'slope': expected an angle in [-0.35, 0.35] [rad], got 30"),
            std::string::npos)
      << steep;
}

}  // namespace
}  // namespace gaitopt::test
