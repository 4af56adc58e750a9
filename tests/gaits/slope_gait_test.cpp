// The polynomial gait of Mu ch. 3 on a slope: designed in the ground frame with gravity
// rotated (dynamics/model.hpp), it still satisfies the dynamics exactly, and its energy balance
// is the physics of walking uphill: over one step the net actuator work equals the potential
// gained, m g step_length sin(gamma), since the gait is periodic and touches down without impact
// (kinetic energy change 0). Also the `slope` key of the gait file.
#include <gtest/gtest.h>

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

TEST(PolynomialGaitOnASlope, DynamicsHoldAndNetWorkEqualsThePotentialGained) {
  const double gamma = 0.1;  // uphill [rad]
  const dynamics::Model model = dynamics::withSlope(loadNamed("mu2004_five_link"), gamma);
  gaits::GaitParams params = gaits::loadGait(kGait);
  params.slope = gamma;
  const gaits::HipPlanSearch search = gaits::searchHipPlan(model, params);
  const gaits::Trajectory traj =
      gaits::buildTrajectory(gaits::PolynomialGait(model, params, search.plan), model, 1000);

  // Inverse dynamics on the sloped model: the residual of (2.7) / (2.11) vanishes.
  const double residual = gaits::maxDynamicsResidual(traj, model);
  EXPECT_LT(residual, 1e-8);
  // Impactless and periodic: the kinetic energy does not change over the step.
  EXPECT_LT(gaits::touchdownVelocityJump(traj, model), 1e-9);
  EXPECT_LT(gaits::periodicityError(traj, model), 1e-9);
  const auto& first = traj.knots().front();
  const auto& last = traj.knots().back();
  const double dk = dynamics::kineticEnergy<double>(model, last.theta, last.dtheta) -
                    dynamics::kineticEnergy<double>(model, first.theta, first.dtheta);

  const double lift = model.totalMass() * model.gravity() * traj.stepLength() * std::sin(gamma);
  const double work = netWork(traj);
  const double err = std::abs(work - (lift + dk)) / lift;
  RecordProperty("net_work_J", fmt::format("{:.4f}", work));
  RecordProperty("potential_gain_J", fmt::format("{:.4f}", lift));
  RecordProperty("kinetic_change_J", fmt::format("{:.2e}", dk));
  RecordProperty("relative_balance_error", fmt::format("{:.2e}", err));
  EXPECT_LT(std::abs(dk), 1e-6 * lift);
  EXPECT_LT(err, 0.01);
  // Uphill the ground pushes the robot up the slope on average: the mean tangential force equals
  // m g sin(gamma) (momentum over a periodic step), so the stance force points uphill.
  double impulse_x = 0;
  const auto& knots = traj.knots();
  for (size_t k = 0; k + 1 < knots.size(); ++k) {
    auto fx = [](const gaits::Knot& q) { return q.force_stance(0) + q.force_swing(0); };
    impulse_x += 0.5 * (fx(knots[k]) + fx(knots[k + 1])) * (knots[k + 1].t - knots[k].t);
  }
  RecordProperty("mean_tangential_force_N", fmt::format("{:.3f}", impulse_x / traj.duration()));
  EXPECT_NEAR(impulse_x / traj.duration(), model.totalMass() * model.gravity() * std::sin(gamma),
              0.01 * model.totalMass() * model.gravity() * std::sin(gamma));
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
