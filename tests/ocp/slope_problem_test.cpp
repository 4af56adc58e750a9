// The RABBIT gait problem of Kelly (2017) on slopes of +-0.05 rad, on a coarse mesh:
// it converges, and the optimum obeys the energy balance of a periodic step with an impact,
//   integral of sum_j tau_j dq_j dt = m g L sin(gamma) + (K^- - K^+),
// the potential gained along the slope plus the kinetic energy the heel strike absorbs (the
// relabelled post-impact state is the start state, so the other kinetic terms cancel). Walking
// uphill costs more torque than on the level, downhill less. Also the `slope` key of OCP files.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include <fmt/format.h>

#include "config/config_error.hpp"
#include "dynamics/energy.hpp"
#include "dynamics/impact/impact.hpp"
#include "dynamics/joint_coordinates.hpp"
#include "ocp/guess/initial_guess.hpp"
#include "ocp/problem/gait_problem.hpp"
#include "ocp/problem/ocp_config.hpp"
#include "ocp/solve/ipopt_adapter.hpp"

namespace gaitopt::ocp {
namespace {

const std::string kSlopeConfig =
    std::string(GAITOPT_SOURCE_DIR) + "/configs/ocp/rabbit_kelly2017.yaml";

struct SlopeSolve {
  SolveResult result;
  double net_work = 0;      ///< integral of sum_j tau_j dq_j over the step [J]
  double lift = 0;          ///< m g L sin(gamma) [J]
  double impact_loss = 0;   ///< K^- - K^+ of the closed-form single impact (Mu 2.35-2.36) [J]
  double kinetic_drop = 0;  ///< K(end) - K(start) along the solution [J]
};

/// Solves RABBIT on `slope` with 10 Hermite-Simpson segments (guess built on the sloped model).
SlopeSolve solveOnSlope(double slope) {
  OcpConfig c = loadOcpConfig(kSlopeConfig);
  c.slope = slope;
  c.phases.front().segments = 10;
  const dynamics::Model model = problemModel(c);
  EXPECT_EQ(model.slope(), slope);
  const GaitProblem problem = buildGaitProblem(model, c, polynomialGuess(model, c));
  SlopeSolve s{solveWithIpopt(problem.nlp, c.solver)};
  // Dense samples from the scheme's own polynomials, so the quadrature error is negligible next
  // to the collocation error.
  const gaits::Trajectory traj = reconstructDense(problem, model, s.result.x, 5000);
  const auto& knots = traj.knots();
  auto power = [](const gaits::Knot& k) { return k.tau.dot(dynamics::toJoint(VecD(k.dtheta))); };
  for (size_t k = 0; k + 1 < knots.size(); ++k)
    s.net_work += 0.5 * (power(knots[k]) + power(knots[k + 1])) * (knots[k + 1].t - knots[k].t);
  s.lift = model.totalMass() * model.gravity() * c.step_length * std::sin(slope);
  const auto& end = knots.back();
  const auto impact = dynamics::singleImpact(model, VecD(end.theta), VecD(end.dtheta));
  const double k_minus = dynamics::kineticEnergy<double>(model, end.theta, end.dtheta);
  // After a single impact the old stance tip B moves (E is at rest): K^+ with B's velocity.
  s.impact_loss = k_minus - dynamics::kineticEnergy<double>(model, end.theta, impact.dtheta_plus,
                                                            impact.trailing_velocity);
  s.kinetic_drop =
      k_minus - dynamics::kineticEnergy<double>(model, knots.front().theta, knots.front().dtheta);
  return s;
}

TEST(RabbitOnASlope, NetWorkEqualsPotentialGainPlusImpactLossAndUphillCostsMore) {
  const SlopeSolve up = solveOnSlope(0.05);
  const SlopeSolve level = solveOnSlope(0.0);
  const SlopeSolve down = solveOnSlope(-0.05);
  for (const auto* s : {&up, &level, &down}) {
    ASSERT_EQ(s->result.status, "Solve_Succeeded");
    EXPECT_LT(s->result.max_violation, 1e-6);
    // Periodicity: the relabelled post-impact state is the start state (same kinetic energy).
    EXPECT_NEAR(s->impact_loss, s->kinetic_drop, 1e-4 * (1 + s->impact_loss));
  }
  for (const auto& [name, s] :
       {std::pair{"up", &up}, std::pair{"level", &level}, std::pair{"down", &down}}) {
    const double expected = s->lift + s->impact_loss;
    // Relative to the larger of the terms: on the level the balance is the impact loss alone.
    const double scale = std::max({std::abs(s->lift), s->impact_loss, std::abs(s->net_work)});
    const double err = std::abs(s->net_work - expected) / scale;
    RecordProperty(fmt::format("{}_cost", name), fmt::format("{:.3f}", s->result.cost));
    RecordProperty(fmt::format("{}_net_work_J", name), fmt::format("{:.4f}", s->net_work));
    RecordProperty(fmt::format("{}_lift_J", name), fmt::format("{:.4f}", s->lift));
    RecordProperty(fmt::format("{}_impact_loss_J", name), fmt::format("{:.4f}", s->impact_loss));
    RecordProperty(fmt::format("{}_balance_error", name), fmt::format("{:.2e}", err));
    // Only the collocation error of 10 Hermite-Simpson segments remains (about 5e-5 measured).
    EXPECT_LT(err, 1e-3) << name << ": net work " << s->net_work << " J, expected " << expected;
  }
  EXPECT_GT(up.result.cost, level.result.cost);
  EXPECT_GT(level.result.cost, down.result.cost);
}

/// The ConfigError message of loading the shipped config with `line` appended, or the slope.
std::string configError(const std::string& line) {
  const auto path =
      std::filesystem::temp_directory_path() / fmt::format("gaitopt_ocp_slope_{}.yaml", ::getpid());
  {
    std::ifstream in(kSlopeConfig);
    std::ofstream out(path);
    // Paths in the config are relative to its folder: make them absolute.
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    for (const std::string key : {"robot: ", "initial_guess: "}) {
      const auto at = text.find(key);
      text.insert(at + key.size(), std::string(GAITOPT_SOURCE_DIR) + "/configs/ocp/");
    }
    out << text << '\n' << line << '\n';
  }
  std::string message;
  try {
    message = fmt::format("no error, slope {}", loadOcpConfig(path.string()).slope);
  } catch (const config::ConfigError& e) {
    message = e.what();
  }
  std::filesystem::remove(path);
  return message;
}

TEST(OcpConfigSlope, DefaultsToLevelAndRejectsDegreesAndSteepSlopes) {
  EXPECT_EQ(loadOcpConfig(kSlopeConfig).slope, 0.0);
  EXPECT_EQ(problemModel(loadOcpConfig(kSlopeConfig)).slope(), 0.0);
  EXPECT_EQ(configError("slope: 0.05"), "no error, slope 0.05");
  const std::string degrees = configError("slope: -3");
  EXPECT_NE(degrees.find("key 'slope': expected an angle in [-0.35, 0.35] [rad] (degrees? -3 deg "
                         "is -0.05236 rad), got -3"),
            std::string::npos)
      << degrees;
  const std::string steep = configError("slope: -25");
  EXPECT_NE(steep.find("key 'slope': expected an angle in [-0.35, 0.35] [rad], got -25"),
            std::string::npos)
      << steep;
}

}  // namespace
}  // namespace gaitopt::ocp
