// The jerk bound (ocp/problem/jerk_limit.hpp): the solved points' accelerations change no faster
// than the bound, and the dense export's angles are then smooth enough that central differences of
// its 1 kHz samples meet its rates to h^2/6 max|theta'''| <= h^2 J / 3 (Hermite-Simpson's
// quadratic accelerations have end slopes at most twice the bound on their half-segments),
// which the unbounded default optimum misses.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "dynamics/robot_files/robot_config.hpp"
#include "ocp/guess/initial_guess.hpp"
#include "ocp/problem/gait_problem.hpp"
#include "ocp/solve/ipopt_adapter.hpp"
#include "support/steepest_change.hpp"

namespace gaitopt::ocp {
namespace {

constexpr double kJerk = 5000;  // rad/s^3; the default optimum reaches about 4e4
constexpr double kRate = 1000;  // Hz

struct JerkSolve {
  GaitProblem problem;
  SolveResult result;
};

JerkSolve solveDefaultJerk(const dynamics::Model& model, double jerk) {
  auto c = loadOcpConfig(std::string(GAITOPT_SOURCE_DIR) + "/configs/ocp/mu2004_walk.yaml");
  c.jerk_limit = jerk;
  JerkSolve s{buildGaitProblem(model, c, polynomialGuess(model, c)), {}};
  s.result = solveWithIpopt(s.problem.nlp, c.solver);
  return s;
}

/// The largest |(theta_{i+1} - theta_{i-1}) / 2h - dtheta_i| over the export's samples inside
/// a phase [rad/s].
double centralDifferenceError(const gaits::Trajectory& dense) {
  const auto& k = dense.knots();
  double worst = 0;
  for (size_t i = 1; i + 1 < k.size(); ++i) {
    const double h = k[i + 1].t - k[i].t;
    if (k[i - 1].phase != k[i].phase || k[i + 1].phase != k[i].phase ||
        std::abs(k[i].t - k[i - 1].t - h) > 1e-9 || std::abs(h - 1 / kRate) > 1e-9)
      continue;
    const VecD d = (VecD(k[i + 1].theta) - VecD(k[i - 1].theta)) / (2 * h);
    worst = std::max(worst, (d - VecD(k[i].dtheta)).cwiseAbs().maxCoeff());
  }
  return worst;
}

TEST(JerkLimit, BoundsThePointsAndMakesTheExportsDifferencesMeetItsRates) {
  const auto model = dynamics::loadRobot(std::string(GAITOPT_SOURCE_DIR) +
                                         "/configs/robots/mu2004_five_link.yaml");
  const JerkSolve s = solveDefaultJerk(model, kJerk);
  ASSERT_TRUE(s.result.success) << s.result.status;
  const gaits::Trajectory points = reconstruct(s.problem, model, s.result.x);
  EXPECT_LT(test::steepestChange(points, &gaits::Knot::ddtheta), kJerk * (1 + 1e-6));
  const double h = 1 / kRate;
  const double bound = h * h * kJerk / 3;
  EXPECT_LT(centralDifferenceError(reconstructDense(s.problem, model, s.result.x, kRate)), bound);

  const JerkSolve free = solveDefaultJerk(model, 0);
  ASSERT_TRUE(free.result.success) << free.result.status;
  EXPECT_GT(centralDifferenceError(reconstructDense(free.problem, model, free.result.x, kRate)),
            2 * bound);
  EXPECT_GT(s.result.cost, free.result.cost);  // the bound is active and costs torque
}

}  // namespace
}  // namespace gaitopt::ocp
