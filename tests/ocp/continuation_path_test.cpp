// The continuation's parts (ocp/solve/continuation*.hpp, ipopt_adapter.hpp) on problems that
// solve in a fraction of a second: the config section and its checks, the path's parameters at
// both ends and between them, Ipopt's primal-dual warm start, the best accepted iterate, the path
// recorded in summary.json, and a failed stage retried with larger barriers.
#include <cmath>
#include <numeric>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "ocp/guess/initial_guess.hpp"
#include "ocp/solve/continuation_path.hpp"
#include "ocp/solve/solution_report.hpp"
#include "support/solved_config.hpp"

namespace gaitopt::ocp {
namespace {

using test::shippedOcpConfig;

/// The ConfigError text of loading configs/ocp/NAME.yaml with `overrides`, or "".
std::string continuationLoadError(const std::string& name,
                                  const std::vector<config::Override>& overrides) {
  try {
    loadOcpConfig(shippedOcpConfig(name), overrides);
  } catch (const config::ConfigError& e) {
    return e.what();
  }
  return "";
}

TEST(ContinuationConfig, SectionIsReadAndCheckedAgainstTheProblem) {
  EXPECT_FALSE(loadOcpConfig(shippedOcpConfig("mu2004_walk")).continuation.enabled);
  const OcpConfig c = loadOcpConfig(shippedOcpConfig("mu2004_walk"),
                                    {{"continuation.steps", "3"},
                                     {"continuation.spacing", "linear"},
                                     {"continuation.parameters", "[margins, strike]"},
                                     {"continuation.sequential", "true"},
                                     {"continuation.retry_mu_init", "[0.5]"},
                                     {"continuation.mesh", "{segments: [12, 3], until: 0.5}"}});
  const ContinuationOptions& o = c.continuation;
  EXPECT_TRUE(o.enabled);
  EXPECT_EQ(o.steps, 3);
  EXPECT_FALSE(o.geometric);
  EXPECT_EQ(o.parameters, (std::vector<std::string>{"margins", "strike"}));
  EXPECT_TRUE(o.sequential);
  EXPECT_EQ(o.retry_mu_init, std::vector<double>{0.5});
  EXPECT_EQ(o.mesh_segments, (std::vector<int>{12, 3}));
  EXPECT_EQ(o.mesh_until, 0.5);
  EXPECT_TRUE(loadOcpConfig(shippedOcpConfig("mu2004_walk"), {{"continuation.parameters", "none"}})
                  .continuation.parameters.empty());

  const auto fails = [](const std::vector<config::Override>& set, const std::string& expected) {
    const std::string e = continuationLoadError("mu2004_walk", set);
    EXPECT_NE(e.find(expected), std::string::npos) << "got: " << e;
  };
  fails({{"continuation.steps", "0"}}, "key 'continuation.steps'");
  fails({{"continuation.steps", "2.5"}}, "expected a whole number in [1, 100]");
  fails({{"continuation.parameters", "[margins, margins]"}}, "'margins' is listed twice");
  fails({{"continuation.parameters", "[none, cost]"}}, "expected `none` alone");
  fails({{"continuation.parameters", "[speed]"}}, "continuation.parameters[0]");
  fails({{"continuation.mesh", "{segments: [12]}"}}, "expected one count per phase (2), got 1");
  fails({{"continuation.bogus", "1"}}, "bogus");
  fails({{"cost", "{abs_work: 1.0}"}, {"continuation.steps", "2"}},
        "expected cost.torque_squared > 0");
}

TEST(ContinuationPath, TheLeastNormalForceIsAMarginThatStartsAtZero) {
  OcpConfig target = loadOcpConfig(shippedOcpConfig("mu2004_walk_cot"));
  target.min_normal_force = 40;  // [N]
  EXPECT_EQ(configAt(target, 0).min_normal_force, 0.0);
  EXPECT_DOUBLE_EQ(configAt(target, 0.5).min_normal_force, 20);
  EXPECT_EQ(configAt(target, 1).min_normal_force, 40);
  EXPECT_EQ(pathParameters(configAt(target, 0.25)).min_normal_force, 10);
}

TEST(ContinuationPath, EndsAreTheEasyAndTheConfiguredProblemAndWeightsMoveGeometrically) {
  const OcpConfig target = loadOcpConfig(shippedOcpConfig("mu2004_walk_cot"));
  ASSERT_TRUE(target.continuation.enabled);
  const double cot = target.cost.cost_of_transport, start = target.continuation.cost_start;
  const OcpConfig easy = configAt(target, 0);
  EXPECT_EQ(easy.friction_margin, 0.0);
  EXPECT_EQ(easy.zmp_margin, 0.0);
  EXPECT_EQ(easy.cost.torque_squared, target.cost.torque_squared);  // kept
  EXPECT_DOUBLE_EQ(easy.cost.cost_of_transport, start * cot);
  const OcpConfig end = configAt(target, 1);
  EXPECT_EQ(end.friction_margin, target.friction_margin);
  EXPECT_EQ(end.zmp_margin, target.zmp_margin);
  EXPECT_EQ(end.cost.cost_of_transport, cot);
  // Half way: margins (from 0) at half their value, the weight at the geometric mean of its ends.
  const OcpConfig half = configAt(target, 0.5);
  EXPECT_DOUBLE_EQ(half.friction_margin, target.friction_margin / 2);
  EXPECT_DOUBLE_EQ(half.zmp_margin, target.zmp_margin / 2);
  EXPECT_DOUBLE_EQ(half.cost.cost_of_transport, std::sqrt(start * cot * cot));
  OcpConfig linear = target;
  linear.continuation.geometric = false;
  EXPECT_DOUBLE_EQ(configAt(linear, 0.5).cost.cost_of_transport, (start * cot + cot) / 2);
  // One group after the other: the margins over the first half, the weights over the second.
  OcpConfig sequential = target;
  sequential.continuation.sequential = true;
  EXPECT_DOUBLE_EQ(configAt(sequential, 0.25).friction_margin, target.friction_margin / 2);
  EXPECT_DOUBLE_EQ(configAt(sequential, 0.25).cost.cost_of_transport, start * cot);
  EXPECT_DOUBLE_EQ(configAt(sequential, 0.5).friction_margin, target.friction_margin);
  EXPECT_DOUBLE_EQ(configAt(sequential, 0.75).cost.cost_of_transport, std::sqrt(start * cot * cot));
}

TEST(ContinuationPath, TheStrikeVelocityMovesFromZeroAndGroupsNotListedStayConfigured) {
  OcpConfig target = loadOcpConfig(shippedOcpConfig("mu2004_walk_strike"));
  target.continuation.parameters = {"strike"};
  const OcpConfig easy = configAt(target, 0), half = configAt(target, 0.5);
  EXPECT_EQ(easy.touchdown.normal_min, 0.0);
  EXPECT_DOUBLE_EQ(half.touchdown.normal_min, target.touchdown.normal_min / 2);
  EXPECT_EQ(easy.touchdown.normal_max, target.touchdown.normal_max);
  EXPECT_EQ(easy.friction_margin, target.friction_margin);  // margins not listed
  EXPECT_TRUE(pathMoves(target));
  target.continuation.parameters = {"cost"};  // a torque-squared problem has no other weight
  EXPECT_FALSE(pathMoves(target));
  EXPECT_EQ(configAt(target, 0).touchdown.normal_min, target.touchdown.normal_min);
}

TEST(ContinuationPath, EveryStageHasTheConfiguredVariablesAndRows) {
  // The precondition of a primal-dual warm start from one stage to the next.
  const OcpConfig target = loadOcpConfig(shippedOcpConfig("mu2004_walk_cot"));
  const dynamics::Model model = problemModel(target);
  const gaits::Trajectory guess = initialGuess(model, target);
  const GaitProblem end = buildGaitProblem(model, target, guess);
  for (const double p : {0.0, 0.5}) {
    const GaitProblem stage = buildGaitProblem(model, configAt(target, p), guess);
    EXPECT_EQ(stage.nlp.variables(), end.nlp.variables()) << "progress " << p;
    EXPECT_EQ(stage.nlp.constraints(), end.nlp.constraints()) << "progress " << p;
  }
}

TEST(IpoptWarmStart, FromItsOwnPrimalDualOptimumTheSolveEndsAtOnce) {
  const test::SolvedConfig s(loadOcpConfig(shippedOcpConfig("mu2004_walk")));
  ASSERT_TRUE(s.result.success);
  const Multipliers& m = s.result.multipliers;
  ASSERT_EQ(m.lambda.size(), s.problem.nlp.constraints());
  ASSERT_EQ(m.z_lower.size(), s.problem.nlp.variables());
  const WarmStart start{s.result.x, m};
  const SolveResult warm = solveWithIpopt(s.problem.nlp, warmStarted(s.config.solver), &start);
  const WarmStart primal{s.result.x, {}};
  const SolveResult cold_duals =
      solveWithIpopt(s.problem.nlp, warmStarted(s.config.solver), &primal);
  ASSERT_TRUE(warm.success);
  RecordProperty("iterations_primal_dual_primal",
                 std::to_string(warm.iterations) + " " + std::to_string(cold_duals.iterations));
  // Measured: 1 iteration from the primal-dual optimum, 7 from its primal point alone.
  EXPECT_LT(warm.iterations, cold_duals.iterations);
  EXPECT_LE(warm.iterations, 3);
  EXPECT_NEAR(warm.cost, s.result.cost, 1e-6 * s.result.cost);
  const WarmStart wrong{s.result.x.head(3), {}};
  EXPECT_THROW(solveWithIpopt(s.problem.nlp, s.config.solver, &wrong), std::invalid_argument);
}

TEST(IpoptBestIterate, IsAnAcceptedIterateWithTheViolationAndCostItRecords) {
  OcpConfig c = loadOcpConfig(shippedOcpConfig("mu2004_walk"));
  c.solver.max_iterations = 4;
  const test::SolvedConfig s(c);
  ASSERT_FALSE(s.result.success);
  const BestIterate& best = s.result.best_iterate;
  const Nlp& nlp = s.problem.nlp;
  ASSERT_EQ(best.x.size(), nlp.variables());
  const Violation row = nlp.worstConstraint(best.x), bound = nlp.worstBound(best.x);
  EXPECT_NEAR(best.violation, std::max(row.amount, bound.amount), 1e-12);
  EXPECT_NEAR(best.cost, nlp.cost(best.x), 1e-12 * std::abs(best.cost));
  EXPECT_EQ(best.feasible, best.violation <= c.solver.constraint_tolerance);
  // The polynomial guess misses the dynamics by far more than four Newton-like steps leave.
  const Eigen::VectorXd& x0 = nlp.initialGuess();
  EXPECT_LT(best.violation, std::max(nlp.worstConstraint(x0).amount, nlp.worstBound(x0).amount));
}

/// The default problem with a continuation of its friction margin in `steps` linear steps.
OcpConfig marginPath(int steps) {
  OcpConfig c = loadOcpConfig(shippedOcpConfig("mu2004_walk"));
  c.continuation.enabled = true;
  c.continuation.parameters = {"margins"};
  c.continuation.steps = steps;
  c.continuation.geometric = false;
  return c;
}

TEST(Continuation, PathIsRecordedInSummaryJsonAndEndsAtTheDirectOptimum) {
  const OcpConfig c = marginPath(3);
  const dynamics::Model model = problemModel(c);
  const gaits::Trajectory guess = initialGuess(model, c);
  const GaitSolution s = solveGait(model, c, guess);
  ASSERT_TRUE(s.result.success) << s.result.status;
  const auto summary = solutionSummary({}, model, c, s, nullptr,
                                       reconstructDense(s.problem, model, s.result.x, 1000));
  // the settings that chose the path: which groups moved, and how
  EXPECT_EQ(summary.at("continuation").at("parameters"), std::vector<std::string>{"margins"});
  EXPECT_EQ(summary.at("continuation").at("sequential"), false);
  const auto& stages = summary.at("continuation").at("stages");
  ASSERT_EQ(stages.size(), 4u);
  int iterations = 0;
  for (size_t k = 0; k < stages.size(); ++k) {
    const auto& stage = stages[k];
    const double progress = static_cast<double>(k) / 3;
    EXPECT_NEAR(stage.at("progress").get<double>(), progress, 1e-12);
    // The margin moves linearly from 0 to the configured 0.15 (of mu).
    EXPECT_NEAR(stage.at("parameters").at("friction_margin").get<double>(),
                progress * c.friction_margin, 1e-12);
    EXPECT_EQ(stage.at("start"), k == 0 ? "initial guess" : "previous stage");
    EXPECT_EQ(stage.at("status"), "Solve_Succeeded");
    EXPECT_EQ(stage.at("segments"), (std::vector<int>{30, 6}));
    iterations += stage.at("iterations").get<int>();
    // Each stage started from the last one's primal-dual solution is shorter than the first.
    if (k > 0) {
      EXPECT_LT(stage.at("iterations").get<int>(), stages[0].at("iterations").get<int>());
    }
  }
  EXPECT_EQ(summary.at("iterations").get<int>(), iterations);
  EXPECT_EQ(stages.back().at("cost").get<double>(), summary.at("cost").get<double>());
  // The configured problem solved directly from the guess lands on the same optimum.
  OcpConfig direct = c;
  direct.continuation.enabled = false;
  const GaitSolution d = solveGait(model, direct, guess);
  ASSERT_TRUE(d.result.success);
  EXPECT_NEAR(s.result.cost, d.result.cost, 1e-6 * d.result.cost);
  EXPECT_FALSE(solutionSummary({}, model, direct, d, nullptr,
                               reconstructDense(d.problem, model, d.result.x, 1000))
                   .contains("continuation"));
}

TEST(Continuation, AStageIpoptEndsWithoutSuccessIsRetriedWarmThenWithLargerBarriers) {
  OcpConfig c = marginPath(1);
  c.continuation.parameters.clear();  // a single stage: the configured problem
  c.solver.max_iterations = 3;        // too few for any start
  const dynamics::Model model = problemModel(c);
  const GaitSolution s = solveGait(model, c, initialGuess(model, c));
  EXPECT_FALSE(s.result.success);
  const auto& path = s.continuation;
  ASSERT_EQ(path.size(), 4u);  // the stage and its three retries, then the continuation gives up
  const std::vector<std::string> starts{"initial guess", "best iterate", "best iterate",
                                        "best iterate"};
  const std::vector<double> barriers{c.solver.mu_init, 1e-5, 0.1, 1.0};
  for (size_t k = 0; k < path.size(); ++k) {
    EXPECT_EQ(path[k].start, starts[k]);
    EXPECT_EQ(path[k].mu_init, barriers[k]);
    EXPECT_EQ(path[k].status, "Maximum_Iterations_Exceeded");
    EXPECT_EQ(path[k].iterations, 3);
    EXPECT_EQ(path[k].progress, 1.0);  // nothing to move: the easy problem is the target
  }
  EXPECT_EQ(s.result.iterations, 12);
}

}  // namespace
}  // namespace gaitopt::ocp
