// The RABBIT gait problem of Kelly (2017): exact derivatives of the whole NLP (dynamics,
// impact, relabelling links, costs) against central differences, convergence from the
// polynomial guess, and an independent check of the optimum (closed-form impact map, forward
// re-simulation of the optimal torques).
#include <gtest/gtest.h>

#include <fmt/format.h>

#include "dynamics/impact/impact.hpp"
#include "dynamics/impact/relabel.hpp"
#include "dynamics/robot_files/robot_config.hpp"
#include "dynamics/ssp_dynamics.hpp"
#include "gaits/export/consistency.hpp"
#include "gaits/export/metrics.hpp"
#include "ocp/guess/initial_guess.hpp"
#include "ocp/problem/gait_problem.hpp"
#include "ocp/solve/ipopt_adapter.hpp"
#include "ocp/transcription/collocation_interpolation.hpp"
#include "support/chain_simulation.hpp"
#include "support/nlp_derivatives.hpp"
#include "support/sample_resimulation.hpp"

namespace gaitopt::ocp {
namespace {

const std::string kRabbitConfig =
    std::string(GAITOPT_SOURCE_DIR) + "/configs/ocp/rabbit_kelly2017.yaml";

TEST(RabbitGaitProblem, JacobianAndLagrangianHessianEqualCentralDifferences) {
  auto c = loadOcpConfig(kRabbitConfig);
  c.phases.front().segments = 3;  // small: every column is differenced
  const auto model = dynamics::loadRobot(c.robot_path);
  const GaitProblem p = buildGaitProblem(model, c, polynomialGuess(model, c));
  const test::DerivativeErrors e = test::compareWithCentralDifferences(p.nlp, 0.05);
  RecordProperty("jacobian_relative_error", fmt::format("{:.2e}", e.jacobian));
  RecordProperty("hessian_relative_error", fmt::format("{:.2e}", e.hessian));
  EXPECT_LT(e.jacobian, 1e-6);
  EXPECT_LT(e.hessian, 1e-6);
}

class RabbitSolution : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    config_ = new OcpConfig(loadOcpConfig(kRabbitConfig));
    model_ = new dynamics::Model(dynamics::loadRobot(config_->robot_path));
    problem_ =
        new GaitProblem(buildGaitProblem(*model_, *config_, polynomialGuess(*model_, *config_)));
    result_ = new SolveResult(solveWithIpopt(problem_->nlp, config_->solver));
  }
  static void TearDownTestSuite() {
    delete result_;
    delete problem_;
    delete model_;
    delete config_;
  }
  static OcpConfig* config_;
  static dynamics::Model* model_;
  static GaitProblem* problem_;
  static SolveResult* result_;
};
OcpConfig* RabbitSolution::config_ = nullptr;
dynamics::Model* RabbitSolution::model_ = nullptr;
GaitProblem* RabbitSolution::problem_ = nullptr;
SolveResult* RabbitSolution::result_ = nullptr;

TEST_F(RabbitSolution, ConvergesFromThePolynomialGuess) {
  RecordProperty("cost", fmt::format("{:.4f}", result_->cost));
  RecordProperty("iterations", result_->iterations);
  ASSERT_EQ(result_->status, "Solve_Succeeded");
  EXPECT_LT(result_->max_violation, 1e-6);
  EXPECT_LT(result_->iterations, 100);
  EXPECT_GT(result_->cost, 0.0);
  // Unactuated ankle and torque limits hold at every point.
  const auto traj = reconstruct(*problem_, *model_, result_->x);
  for (const auto& k : traj.knots()) {
    EXPECT_EQ(k.tau(0), 0.0);
    EXPECT_LE(k.tau.cwiseAbs().maxCoeff(), 100.0 + 1e-6);
  }
}

TEST_F(RabbitSolution, GaitoptsKktSolverFollowsMumpsToTheSameOptimum) {
  // The block LDL^T of ocp/solve/kkt/ (the default) against MUMPS on every matrix: Ipopt must take
  // the same steps (same inertia, accurate solves), so the iterations and the optimum agree.
  ASSERT_EQ(config_->solver.linear_solver, "ldl");
  SolverOptions options = config_->solver;
  options.linear_solver = "mumps";
  const SolveResult mumps = solveWithIpopt(problem_->nlp, options);
  ASSERT_EQ(mumps.status, "Solve_Succeeded");
  EXPECT_EQ(result_->iterations, mumps.iterations);
  EXPECT_GE(result_->profile.factorizations, result_->iterations);  // Ipopt called our solver
  // Two counters of the same path: our solver's own (kkt_statistics.hpp) and Ipopt's MUMPS
  // journal; none of our factorizations went to MUMPS, and Ipopt corrected the same inertias.
  EXPECT_EQ(result_->profile.factorizations, mumps.profile.factorizations);
  EXPECT_EQ(result_->profile.ldl.mumps_fallbacks, 0);
  EXPECT_EQ(result_->profile.inertia_corrections, mumps.profile.inertia_corrections);
  EXPECT_NEAR(result_->cost, mumps.cost, 1e-8 * mumps.cost);
  EXPECT_LT((result_->x - mumps.x).lpNorm<Eigen::Infinity>(), 1e-6);
}

TEST_F(RabbitSolution, ClosedFormImpactAndRelabelReturnToTheStart) {
  // Independent of the optimiser's implicit impact: Mu's closed-form single impact (2.35-2.36)
  // applied to the optimal strike state, then relabelling (2.38), gives the optimal start.
  const auto traj = reconstruct(*problem_, *model_, result_->x);
  const auto& end = traj.knots().back();
  const auto& start = traj.knots().front();
  const auto impact = dynamics::singleImpact(*model_, VecD(end.theta), VecD(end.dtheta));
  EXPECT_TRUE(impact.unilateral_ok);  // the old stance tip lifts off
  const VecD theta = dynamics::relabelAngles<double>(*model_, end.theta);
  const VecD dtheta = dynamics::relabelRates<double>(impact.dtheta_plus);
  EXPECT_LT((theta - VecD(start.theta)).cwiseAbs().maxCoeff(), 1e-7);
  EXPECT_LT((dtheta - VecD(start.dtheta)).cwiseAbs().maxCoeff(), 1e-6);
}

TEST_F(RabbitSolution, SummaryMetricsSeeTheSingleImpact) {
  // The step ends at its strike; periodicity holds through the impact map (Mu 2.36a, 2.38),
  // and the impact's loss from the closed-form map equals the NLP's own impact variables'.
  const auto traj = reconstruct(*problem_, *model_, result_->x);
  const double loss = gaits::impactEnergyLoss(traj, *model_);
  RecordProperty("periodicity_error",
                 fmt::format("{:.2e}", gaits::periodicityError(traj, *model_)));
  RecordProperty("impact_energy_loss_J", fmt::format("{:.4f}", loss));
  EXPECT_LT(gaits::periodicityError(traj, *model_), 1e-6);
  EXPECT_GT(loss, 1.0);  // a heel strike at walking speed, not a soft landing
  EXPECT_NEAR(loss, *problem_->touchdown.energyLoss(*model_, result_->x), 1e-6);
  EXPECT_GT(gaits::touchdownVelocityJump(traj, *model_), 0.1);
}

TEST(RabbitKelly2017, ShortStepCostMatchesThePublishedGpopsValue) {
#ifndef NDEBUG
  GTEST_SKIP() << "a fine-mesh solve: optimised builds only";
#endif
  // Kelly (SIAM Review 2017, sec. 7) reports 263.70 for a 0.4 m step in 0.6 s (GPOPS-II);
  // an independent reproduction gave 263.44. Our Hermite-Simpson optimum within 0.5 %.
  auto c = loadOcpConfig(kRabbitConfig);
  c.step_length = 0.4;
  c.phases.front().duration = 0.6;
  c.solver.tolerance = 1e-8;
  const auto model = dynamics::loadRobot(c.robot_path);
  const GaitProblem p = buildGaitProblem(model, c, polynomialGuess(model, c));
  const SolveResult r = solveWithIpopt(p.nlp, c.solver);
  ASSERT_EQ(r.status, "Solve_Succeeded");
  RecordProperty("cost", fmt::format("{:.3f}", r.cost));
  EXPECT_NEAR(r.cost, 263.70, 0.005 * 263.70);
}

TEST_F(RabbitSolution, ForwardSimulationOfTheOptimalTorquesReproducesTheStates) {
  // The solver's torques (Hermite-Simpson's quadratics) integrated over the whole step from the
  // optimum's first state, compared with the 1 kHz export at every sample, not only at the
  // solver's points: the error is the collocation's, grown by the open loop (measured 9.9e-4
  // rad at the points).
  const gaits::Trajectory dense = reconstructDense(*problem_, *model_, result_->x, 1000.0);
  const PhaseLayout& l = problem_->ssp.layout;
  const Slice u = problem_->ssp.point.u;
  auto torque = [&](double t) -> VecD {
    const Eigen::VectorXd point = interpolatePoint(l, result_->x, t);
    return u.of(point);
  };
  std::vector<double> times;
  for (const auto& k : dense.knots()) times.push_back(k.t);
  double max_err = 0;
  size_t index = 0;
  const auto& k0 = dense.knots().front();
  test::simulateSsp(*model_, k0.theta, k0.dtheta, torque, times, 1e-10,
                    [&](double, const VecD& theta, const VecD&) {
                      const VecD ref = dense.knots()[index++].theta;
                      max_err = std::max(max_err, (theta - ref).cwiseAbs().maxCoeff());
                    });
  RecordProperty("resimulation_max_angle_error_rad", fmt::format("{:.3e}", max_err));
  EXPECT_GT(times.size(), 500u);
  EXPECT_LT(max_err, 3e-3);
}

TEST_F(RabbitSolution, ExportedTorquesReplayedBetweenTheSamplesReachTheNextSample) {
  // What a controller receives: the export's inverse-dynamics torques, linear between its 1 kHz
  // samples (sample_resimulation.hpp).
  const gaits::Trajectory dense = reconstructDense(*problem_, *model_, result_->x, 1000.0);
  const test::SampleResimulation replay = test::resimulateSamples(dense, *model_);
  const double peak = test::peakAcceleration(dense);
  RecordProperty("replay_acceleration_error",
                 fmt::format("{:.2e} of {:.1f} rad/s^2", replay.acceleration_error, peak));
  EXPECT_GT(replay.intervals, 500);
  EXPECT_LT(replay.acceleration_error, 1e-3 * peak);  // measured 6.4e-3 of 28.4 rad/s^2
}

TEST(RabbitAbsoluteWork, DerivativesAreExactAndTheOptimumSpendsLessWork) {
  // The absolute-work cost (slack split of each joint's power) against the torque-squared
  // optimum of the same problem: exact derivatives, convergence, and less absolute work.
  auto c = loadOcpConfig(kRabbitConfig);
  c.cost = CostWeights{.torque_squared = 1e-3, .abs_work = 1.0};
  const auto model = dynamics::loadRobot(c.robot_path);
  const gaits::Trajectory guess = polynomialGuess(model, c);
  c.phases.front().segments = 3;
  const test::DerivativeErrors e =
      test::compareWithCentralDifferences(buildGaitProblem(model, c, guess).nlp, 0.05);
  EXPECT_LT(e.jacobian, 1e-6);
  EXPECT_LT(e.hessian, 1e-6);

  c.phases.front().segments = 10;
  const GaitProblem work_problem = buildGaitProblem(model, c, guess);
  const SolveResult work = solveWithIpopt(work_problem.nlp, c.solver);
  ASSERT_EQ(work.status, "Solve_Succeeded");
  c.cost = CostWeights{.torque_squared = 1.0};
  const GaitProblem sq_problem = buildGaitProblem(model, c, guess);
  const SolveResult sq = solveWithIpopt(sq_problem.nlp, c.solver);
  ASSERT_EQ(sq.status, "Solve_Succeeded");
  const double work_j = gaits::absoluteWork(reconstruct(work_problem, model, work.x));
  const double sq_j = gaits::absoluteWork(reconstruct(sq_problem, model, sq.x));
  RecordProperty("abs_work_optimum_J", fmt::format("{:.3f}", work_j));
  RecordProperty("torque_squared_optimum_work_J", fmt::format("{:.3f}", sq_j));
  EXPECT_LT(work_j, 0.5 * sq_j);

  // The work the optimiser counts is the work of the export a controller receives (5 kHz, the
  // scheme's own polynomials): an optimum of absolute work hides its work wherever the
  // transcription's power and the export's differ.
  double counted_j = 0;
  for (const auto& term : work_problem.nlp.costTerms())
    if (term->name().find("abs_work") != std::string::npos) counted_j += term->value(work.x);
  const double export_j =
      gaits::absoluteWork(reconstructDense(work_problem, model, work.x, 5000.0));
  RecordProperty("abs_work_counted_J", fmt::format("{:.4f}", counted_j));
  RecordProperty("abs_work_export_J", fmt::format("{:.4f}", export_j));
  EXPECT_NEAR(counted_j, export_j, 0.02 * export_j);
}

}  // namespace
}  // namespace gaitopt::ocp
