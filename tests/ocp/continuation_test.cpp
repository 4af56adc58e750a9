// Continuation on the hard shipped problems (ocp/solve/continuation.hpp): the gait designed to be
// walked (configs/ocp/mu2004_walk_robust.yaml) converges at 24 and 36 SSP segments, where a solve
// from the upright polynomial gait stopped at the iteration limit, with gaitopt's own KKT solver
// (the config pins none) and in few iterations from its leaned guess, to optima that meet its
// margins and strike and agree across meshes; and a stage that keeps failing halves the step
// before the continuation gives up.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <fmt/format.h>

#include "gaits/export/metrics.hpp"
#include "ocp/guess/initial_guess.hpp"
#include "ocp/solve/gait_solve.hpp"
#include "support/solved_config.hpp"

namespace gaitopt::ocp {
namespace {

/// A shipped problem solved at `segments` SSP segments from its polynomial gait.
struct ShippedAt {
  OcpConfig config;
  dynamics::Model model;
  GaitSolution solution;

  ShippedAt(const std::string& name, int segments)
      : config(loadOcpConfig(test::shippedOcpConfig(name),
                             {{"phases[0].segments", std::to_string(segments)}})),
        model(problemModel(config)),
        solution(solveGait(model, config, initialGuess(model, config))) {}
};

/// The robust problem (configs/ocp/mu2004_walk_robust.yaml) at `segments` SSP segments.
struct RobustAt : ShippedAt {
  explicit RobustAt(int segments) : ShippedAt("mu2004_walk_robust", segments) {}
};

/// The robust problem's own bounds: friction cones of mu - 0.3 and the ZMP 6 cm inside the foot
/// at the solution's points, and on its 1 kHz export within what the scheme's polynomials give
/// between the points (measured 2026-12-01: a ratio of 0.3036 and a margin of 59.3 mm at 24
/// segments, 0.3009 and 59.9 mm at 36); a strike at 0.04 .. 0.06 m/s.
void expectRobustBoundsHold(const RobustAt& r) {
  const GaitSolution& s = r.solution;
  const gaits::Trajectory knots = reconstruct(s.problem, r.model, s.result.x);
  const double mu = r.model.friction() - 0.3;
  EXPECT_LE(gaits::maxFrictionRatio(knots), mu + 1e-6);
  EXPECT_GE(gaits::minZmpMargin(knots, r.model), 0.06 - 1e-6);
  const gaits::Trajectory dense = reconstructDense(s.problem, r.model, s.result.x, 1000.0);
  ::testing::Test::RecordProperty(fmt::format("dense_friction_zmp_{}", r.config.phases[0].segments),
                                  fmt::format("{:.4f} {:.4f}", gaits::maxFrictionRatio(dense),
                                              gaits::minZmpMargin(dense, r.model)));
  EXPECT_LE(gaits::maxFrictionRatio(dense), mu * (1 + 2e-2));
  EXPECT_GE(gaits::minZmpMargin(dense, r.model), 0.06 - 1e-3);
  const StrikeReport strike = s.problem.touchdown.strike(r.model, s.result.x);
  EXPECT_GE(strike.normal_velocity, 0.04 - 1e-6);
  EXPECT_LE(strike.normal_velocity, 0.06 + 1e-6);
}

TEST(RobustContinuation, ConvergesAt24And36SspSegmentsToOneOptimum) {
  const RobustAt coarse(24), fine(36);
  for (const RobustAt* r : {&coarse, &fine}) {
    const GaitSolution& s = r->solution;
    ASSERT_TRUE(s.result.success) << s.result.status;
    // The last stage is the configured problem on the configured mesh.
    EXPECT_EQ(s.continuation.back().segments,
              (std::vector<int>{r->config.phases[0].segments, r->config.phases[1].segments}));
    EXPECT_EQ(s.continuation.back().progress, 1.0);
    expectRobustBoundsHold(*r);
    // From the guess leaned as the family leans, the short way (53 and 54 iterations measured
    // with the shipped mesh's solve; from the upright gait the paths took 266 to 2000).
    EXPECT_EQ(r->config.solver.linear_solver, "ldl");
    EXPECT_LE(s.result.iterations, 100);
  }
  // The bound on how far the optima at different meshes may lie apart.
  const double a = coarse.solution.result.cost, b = fine.solution.result.cost;
  RecordProperty("costs_24_36", fmt::format("{:.6f} {:.6f}", a, b));
  EXPECT_LT(std::abs(a - b), 0.02 * std::min(a, b));
}

TEST(Continuation, AFailingStageHalvesTheStepBeforeTheContinuationGivesUp) {
  // The robust problem with its margins moved from 0 on its shipped mesh: the path follows a
  // branch of optima that strike moving forward, which ends in a fold near a friction margin of
  // 0.175 (measured), short of the configured 0.3, so the stages past it fail. From the upright
  // polynomial gait, whose easy problem converges (from the config's leaned guess it does not).
  OcpConfig c = loadOcpConfig(test::shippedOcpConfig("mu2004_walk_robust"));
  c.guess_gait_path = std::string(GAITOPT_SOURCE_DIR) + "/configs/gaits/mu2004.yaml";
  c.continuation.parameters = {"margins"};
  c.continuation.mesh_segments.clear();
  c.continuation.steps = 8;
  c.continuation.geometric = false;
  c.continuation.halvings = 2;
  c.continuation.retries = 0;
  c.solver.max_iterations = 60;  // the stages before the fold take at most 34 (measured)
  const dynamics::Model model = problemModel(c);
  const GaitSolution s = solveGait(model, c, initialGuess(model, c));
  EXPECT_FALSE(s.result.success);
  const auto& path = s.continuation;
  ASSERT_GE(path.size(), 2u);
  ASSERT_TRUE(path.front().success);
  // After each failure the next stage tries half the failed step from the last success.
  double accepted = 0, step = 1.0 / c.continuation.steps;
  int failures = 0;
  for (size_t k = 1; k < path.size(); ++k) {
    EXPECT_NEAR(path[k].progress, accepted + step, 1e-12) << "stage " << k;
    EXPECT_NEAR(path[k].parameters.friction_margin, path[k].progress * c.friction_margin, 1e-12);
    if (path[k].success) {
      accepted = path[k].progress;
    } else {
      step /= 2;
      ++failures;
    }
  }
  EXPECT_EQ(failures, c.continuation.halvings + 1);
  EXPECT_FALSE(path.back().success);
}

}  // namespace
}  // namespace gaitopt::ocp
