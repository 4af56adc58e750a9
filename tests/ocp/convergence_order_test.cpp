// Mesh refinement on the RABBIT problem: the optimal cost converges, and the observed order of
// each scheme matches theory (trapezoidal 2, Hermite-Simpson 4). The order is estimated from
// three meshes, p = log2((J_h - J_h/2) / (J_h/2 - J_h/4)), which needs no reference solution.
#include <gtest/gtest.h>

#include <cmath>

#include <fmt/format.h>

#include "dynamics/robot_files/robot_config.hpp"
#include "ocp/guess/initial_guess.hpp"
#include "ocp/problem/gait_problem.hpp"
#include "ocp/solve/ipopt_adapter.hpp"

namespace gaitopt::ocp {
namespace {

double observedOrder(Scheme scheme, int coarsest) {
  auto c = loadOcpConfig(std::string(GAITOPT_SOURCE_DIR) + "/configs/ocp/rabbit_kelly2017.yaml");
  const auto model = dynamics::loadRobot(c.robot_path);
  const gaits::Trajectory guess = polynomialGuess(model, c);
  c.scheme = scheme;
  c.solver.tolerance = 1e-10;  // solver error far below the discretisation error
  std::vector<double> cost;
  for (int segments = coarsest; segments <= 4 * coarsest; segments *= 2) {
    c.phases.front().segments = segments;
    const SolveResult r = solveWithIpopt(buildGaitProblem(model, c, guess).nlp, c.solver);
    EXPECT_EQ(r.status, "Solve_Succeeded") << segments << " segments";
    cost.push_back(r.cost);
  }
  return std::log2(std::abs(cost[0] - cost[1]) / std::abs(cost[1] - cost[2]));
}

TEST(ConvergenceOrder, TrapezoidalIsSecondOrder) {
  const double p = observedOrder(Scheme::kTrapezoidal, 10);
  RecordProperty("trapezoidal_order", fmt::format("{:.2f}", p));
  EXPECT_NEAR(p, 2.0, 0.3);
}

TEST(ConvergenceOrder, HermiteSimpsonIsFourthOrder) {
  const double p = observedOrder(Scheme::kHermiteSimpson, 5);
  RecordProperty("hermite_simpson_order", fmt::format("{:.2f}", p));
  EXPECT_NEAR(p, 4.0, 0.5);
}

}  // namespace
}  // namespace gaitopt::ocp
