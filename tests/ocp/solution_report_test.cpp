// The summary and folders of a gait solution (ocp/solve/solution_report.hpp): the impact's energy
// loss against the kinetic energy the closed-form impact map takes, the between-node metrics of a
// trajectory with known forces, and the folder of a failed solve.
#include <cmath>
#include <filesystem>
#include <numbers>

#include <gtest/gtest.h>

#include "dynamics/impact/impact.hpp"
#include "dynamics/impact/relabel.hpp"
#include "dynamics/robot_files/robot_config.hpp"
#include "dynamics/ssp_dynamics.hpp"
#include "io/io_test_dir.hpp"
#include "io/strict_json.hpp"
#include "ocp/guess/initial_guess.hpp"
#include "ocp/solve/solution_report.hpp"

namespace gaitopt::ocp {
namespace {

/// RABBIT after Kelly 2017 (single impact) on 4 segments: at its initial guess, which lands at
/// rest, or solved.
struct Rabbit {
  OcpConfig config;
  dynamics::Model model;
  GaitSolution solution;

  explicit Rabbit(bool solve)
      : config(
            loadOcpConfig(std::string(GAITOPT_SOURCE_DIR) + "/configs/ocp/rabbit_kelly2017.yaml")),
        model(dynamics::loadRobot(config.robot_path)) {
    config.phases.front().segments = 4;
    if (solve) {
      solution = solveGait(model, config, polynomialGuess(model, config));
      return;
    }
    solution.problem = buildGaitProblem(model, config, polynomialGuess(model, config));
    solution.result.status = "Maximum_Iterations_Exceeded";
    solution.result.iterations = 7;
    solution.result.x = solution.problem.nlp.initialGuess();
    solution.history.push_back({{4}, "Maximum_Iterations_Exceeded", 7, 0, 0, 0});
  }
};

/// 1/2 dtheta^T D(theta) dtheta with the tip at the origin pinned (Mu 2.4 through D of 2.7).
double kineticEnergyFromD(const dynamics::Model& model, const VecD& theta, const VecD& dtheta) {
  return 0.5 * dtheta.dot(dynamics::massMatrix<double>(model, theta) * dtheta);
}

TEST(SolutionSummary, ImpactLossIsTheKineticEnergyTheImpactMapTakes) {
  const Rabbit r(true);
  const GaitSolution& s = r.solution;
  ASSERT_TRUE(s.result.success) << s.result.status;
  const gaits::Trajectory dense = reconstructDense(s.problem, r.model, s.result.x, 200);
  const auto summary =
      solutionSummary({"cfg.yaml", 200, {}, {}, {}}, r.model, r.config, s, nullptr, dense);
  // Before the strike the stance tip B is pinned; after a single impact E is pinned and B lifts
  // off, so the energy after is that of the relabelled chain pinned at E.
  const gaits::Knot strike = reconstruct(s.problem, r.model, s.result.x).knots().back();
  const VecD theta = strike.theta, dtheta = strike.dtheta;
  const VecD plus = dynamics::singleImpact(r.model, theta, dtheta).dtheta_plus;
  const double before = kineticEnergyFromD(r.model, theta, dtheta);
  const double after = kineticEnergyFromD(r.model, dynamics::relabelAngles<double>(r.model, theta),
                                          dynamics::relabelRates<double>(plus));
  ASSERT_GT(before - after, 1.0);  // a real loss [J], not a rounding
  EXPECT_NEAR(summary.at("impact_energy_loss_J").get<double>(), before - after, 1e-5 * before);
  // The share of its friction cone the impulse uses, |P_t| / P_n of the closed-form map's
  // impulse; a single impact leaves the trailing tip none.
  const Vec2d p = dynamics::singleImpact(r.model, theta, dtheta).impulse_leading;
  ASSERT_GT(p.y(), 0.0);
  EXPECT_NEAR(summary.at("strike").at("impulse_leading_cone_ratio").get<double>(),
              std::abs(p.x()) / p.y(), 1e-4);
  EXPECT_TRUE(summary.at("strike").at("impulse_trailing_cone_ratio").is_null());
  EXPECT_EQ(summary.at("converged"), true);
  EXPECT_EQ(summary.at("nlp").at("segments"), std::vector<int>{4});
  EXPECT_EQ(summary.at("between_nodes").at("rate_hz"), 200.0);
  // The KKT record holds the solve's own counts: at least one factorization per iteration.
  const auto& kkt = summary.at("kkt");
  EXPECT_EQ(kkt.at("linear_solver"), r.config.solver.linear_solver);
  EXPECT_EQ(kkt.at("factorizations"), s.result.profile.factorizations);
  EXPECT_GE(kkt.at("factorizations").get<int>(), s.result.iterations);
  EXPECT_EQ(
      kkt.at("mumps_fallback_share").get<double>(),
      static_cast<double>(s.result.profile.ldl.mumps_fallbacks) / s.result.profile.factorizations);
}

/// Three SSP knots of RABBIT standing still, with the given ground forces at B.
gaits::Trajectory standing(const dynamics::Model& model, const std::vector<Vec2d>& forces) {
  std::vector<gaits::Knot> knots;
  for (std::size_t k = 0; k < forces.size(); ++k) {
    gaits::Knot knot;
    knot.t = 0.1 * static_cast<double>(k);
    knot.theta = knot.dtheta = knot.ddtheta = knot.tau = VecD::Zero(model.nLinks());
    knot.force_stance = forces[k];
    knots.push_back(knot);
  }
  return {model.name(), 0.5, knots};
}

TEST(BetweenNodeMetrics, FrictionRatioIsTheWorstTangentialOverNormalForce) {
  const auto model =
      dynamics::loadRobot(std::string(GAITOPT_SOURCE_DIR) + "/configs/robots/rabbit.yaml");
  const auto j = betweenNodeMetrics(standing(model, {{30, 100}, {-60, 400}, {10, 250}}), model, 50);
  EXPECT_DOUBLE_EQ(j.at("max_friction_ratio").get<double>(), 0.3);  // 30 / 100
  EXPECT_DOUBLE_EQ(j.at("min_normal_force").get<double>(), 100);
  EXPECT_DOUBLE_EQ(j.at("rate_hz").get<double>(), 50);
  // At 50 Hz the derivative checks are not judged, and the metrics name them.
  EXPECT_EQ(j.at("unjudged").at("checks"),
            nlohmann::ordered_json({"max_rate_mismatch", "max_acceleration_mismatch"}));
  EXPECT_FALSE(betweenNodeMetrics(standing(model, {{30, 100}, {-60, 400}, {10, 250}}), model, 1000)
                   .contains("unjudged"));
}

// The summary's top-level peak torques and posture are read at the solver's points; these are
// the export's, so a peak or a bent knee between the points shows here.
TEST(BetweenNodeMetrics, PeakTorqueAndPostureAreTheExportsOwn) {
  const auto model =
      dynamics::loadRobot(std::string(GAITOPT_SOURCE_DIR) + "/configs/robots/rabbit.yaml");
  gaits::Trajectory traj = standing(model, {{30, 100}, {10, 400}, {10, 250}});
  std::vector<gaits::Knot> knots = traj.knots();
  knots[1].tau(2) = -42;                  // a torque peak on the third joint at the middle sample
  knots[1].theta(1) = 0.2;                // the stance knee bent by 0.2 rad (thigh against shank)
  knots[1].theta(*model.torso()) = -0.1;  // the torso leaning 0.1 rad
  const auto j = betweenNodeMetrics({model.name(), 0.5, knots}, model, 50);
  const auto peak = j.at("peak_torque").get<std::vector<double>>();
  ASSERT_EQ(peak.size(), static_cast<std::size_t>(model.nLinks()));
  EXPECT_DOUBLE_EQ(peak[2], 42);
  EXPECT_DOUBLE_EQ(peak[0], 0);
  const double deg = 180 / std::numbers::pi;
  EXPECT_NEAR(j.at("posture_deg").at("max_stance_knee_flexion").get<double>(), 0.2 * deg, 1e-12);
  EXPECT_NEAR(j.at("posture_deg").at("max_torso_lean").get<double>(), 0.1 * deg, 1e-12);
  EXPECT_DOUBLE_EQ(j.at("posture_deg").at("max_swing_knee_flexion").get<double>(), 0);
}

TEST(BetweenNodeMetrics, APullingTipHasNoFrictionRatio) {
  const auto model =
      dynamics::loadRobot(std::string(GAITOPT_SOURCE_DIR) + "/configs/robots/rabbit.yaml");
  const auto j = betweenNodeMetrics(standing(model, {{30, 100}, {1, -5}, {10, 250}}), model, 50);
  EXPECT_EQ(j.at("max_friction_ratio"), "unbounded: a normal force <= 0");
  EXPECT_DOUBLE_EQ(j.at("min_normal_force").get<double>(), -5);
}

class FailedResult : public io::test::IoTest {};

TEST_F(FailedResult, IsMarkedAndNamesItsWorstViolation) {
  const Rabbit r(false);
  const std::string failed = path("out.failed");
  std::vector<bool> had_failed_note;  // when the pictures were drawn
  GaitResultOptions options{
      "cfg.yaml",
      100,
      [&](const std::string& dir) {
        had_failed_note.push_back(std::filesystem::exists(dir + "/FAILED.txt"));
      },
      {},
      {}};
  const std::string message = writeFailedResult(options, r.model, r.config, r.solution, failed);
  EXPECT_EQ(message.rfind("solver status Maximum_Iterations_Exceeded after 7 iterations", 0), 0u)
      << message;
  EXPECT_NE(message.find(failed), std::string::npos);
  EXPECT_EQ(had_failed_note, std::vector<bool>{false});  // drawn once, before FAILED.txt
  EXPECT_EQ(slurp(failed + "/FAILED.txt").rfind("This folder holds a failed solve", 0), 0u);
  const auto summary = io::readStrictJson(failed + "/summary.json");
  EXPECT_EQ(summary.at("converged"), false);
  EXPECT_EQ(summary.at("config"), "cfg.yaml");
  const auto& worst = summary.at("worst_violation");
  const Violation expected = r.solution.problem.nlp.worstConstraint(r.solution.result.x);
  EXPECT_EQ(worst.at("constraint"), expected.name);
  EXPECT_GT(worst.at("violation").get<double>(), 0);
  EXPECT_TRUE(std::filesystem::exists(failed + "/trajectory.csv"));
}

}  // namespace
}  // namespace gaitopt::ocp
