// constraints.impulse_friction_margin (OcpConfig::impulse_friction_margin): the impact impulses'
// own friction margin, read strictly, moved by the continuation with the other margins, and a
// pair of solves of the designed strike (configs/ocp/mu2004_walk_strike.yaml) whose impulses
// keep the cone they were given, checked against the frictional impact law of the plants
// (Hurmuzlu, Genot, Brogliato 2001, eqs. 76-82; dynamics/impact/frictional_impact.hpp): with the
// impulses' margin at 0.05 instead of the forces' 0.15 the strike costs less, and the plant's
// impact of the optimum's strike state still leaves both tips at rest. (At a margin of 0 the
// optimum's trailing impulse lies on the cone's edge, where that law finds neither sticking nor
// sliding consistent: the shipped ensemble keeps 0.05.)
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include <fmt/format.h>

#include "dynamics/impact/frictional_impact.hpp"
#include "ocp/guess/initial_guess.hpp"
#include "ocp/problem/gait_problem.hpp"
#include "ocp/solve/continuation_path.hpp"
#include "ocp/solve/gait_solve.hpp"
#include "ocp/solve/resimulation.hpp"
#include "support/edited_config.hpp"
#include "support/solved_config.hpp"

namespace gaitopt::ocp {
namespace {

const std::string kStrikeConfig = test::shippedOcpConfig("mu2004_walk_strike");
const std::string kMargin = "friction_margin: 0.15";

TEST(ImpulseFrictionMarginConfig, DefaultsToTheForcesMarginAndReadsItsOwn) {
  const OcpConfig shipped = loadOcpConfig(kStrikeConfig);
  const dynamics::Model model = problemModel(shipped);
  EXPECT_FALSE(shipped.impulse_friction_margin);
  EXPECT_DOUBLE_EQ(impulseFrictionBound(model, shipped), model.friction() - 0.15);
  OcpConfig own = shipped;
  own.impulse_friction_margin = 0.05;
  EXPECT_DOUBLE_EQ(impulseFrictionBound(model, own), model.friction() - 0.05);
  EXPECT_DOUBLE_EQ(frictionBound(model, own), model.friction() - 0.15);  // forces keep theirs
  own.impulse_friction_margin = model.friction();
  EXPECT_THROW(impulseFrictionBound(model, own), std::invalid_argument);
  EXPECT_EQ(
      test::loadEditedOcpConfig(kStrikeConfig, kMargin, kMargin + "\n  impulse_friction_margin: 0"),
      "");
  const std::string negative = test::loadEditedOcpConfig(
      kStrikeConfig, kMargin, kMargin + "\n  impulse_friction_margin: -0.1");
  EXPECT_NE(negative.find("key 'constraints.impulse_friction_margin'"), std::string::npos)
      << negative;
}

TEST(ImpulseFrictionMarginConfig, MarginsThatLeaveNoConeAreRefusedNamingKeyAndRobotsFriction) {
  // The shipped robot's mu is 0.6: a margin of 0.6 or more leaves no cone.
  for (const std::string key : {"friction_margin", "impulse_friction_margin"}) {
    const std::string edit = key == "friction_margin"
                                 ? "friction_margin: 0.6"
                                 : kMargin + "\n  impulse_friction_margin: 0.7";
    const std::string error = test::loadEditedOcpConfig(kStrikeConfig, kMargin, edit);
    EXPECT_NE(error.find(fmt::format("key 'constraints.{}': expected less than the robot's "
                                     "friction coefficient 0.6",
                                     key)),
              std::string::npos)
        << error;
  }
  EXPECT_EQ(test::loadEditedOcpConfig(kStrikeConfig, kMargin, "friction_margin: 0.59"), "");
}

TEST(ImpulseFrictionMarginConfig, TheContinuationMovesItWithTheMargins) {
  OcpConfig target = loadOcpConfig(kStrikeConfig);  // continuation.parameters: [margins]
  target.impulse_friction_margin = 0.1;
  EXPECT_EQ(*configAt(target, 0).impulse_friction_margin, 0.0);
  EXPECT_DOUBLE_EQ(*configAt(target, 0.5).impulse_friction_margin, 0.05);
  EXPECT_EQ(*configAt(target, 1).impulse_friction_margin, 0.1);
  EXPECT_DOUBLE_EQ(pathParameters(configAt(target, 0.5)).impulse_friction_margin, 0.05);
  target.impulse_friction_margin.reset();  // unset: the impulses follow the forces' margin
  EXPECT_DOUBLE_EQ(pathParameters(configAt(target, 0.5)).impulse_friction_margin,
                   configAt(target, 0.5).friction_margin);
}

/// The strike config solved through its continuation with the impulses' margin `margin`.
struct StrikeSolve {
  explicit StrikeSolve(double margin)
      : config(withMargin(margin)),
        model(problemModel(config)),
        solution(solveGait(model, config, initialGuess(model, config))) {}
  StrikeSolve(const StrikeSolve&) = delete;
  StrikeSolve& operator=(const StrikeSolve&) = delete;

  static OcpConfig withMargin(double margin) {
    OcpConfig c = loadOcpConfig(kStrikeConfig);
    c.impulse_friction_margin = margin;
    return c;
  }
  /// |P_t| / P_n of the NLP's leading (E) and trailing (B) impulses.
  Vec2d impulseRatios() const {
    const StrikeReport s = solution.problem.touchdown.strike(model, solution.result.x);
    return {std::abs(s.impulse_leading.x()) / s.impulse_leading.y(),
            std::abs(s.impulse_trailing.x()) / s.impulse_trailing.y()};
  }
  /// The plants' frictional double impact (the robot's own mu) of the optimum's strike state.
  dynamics::FrictionalImpact plantImpact() const {
    const auto& p = solution.problem;
    const auto [theta, dtheta] = sspPointState(p, solution.result.x, p.ssp.layout.points() - 1);
    return dynamics::frictionalDoubleImpact(model, theta, dtheta, 0.0);
  }

  OcpConfig config;
  dynamics::Model model;
  GaitSolution solution;
};

TEST(ImpulseFrictionMargin, InAWiderConeTheStrikeCostsLessAndThePlantsImpactSticks) {
#ifndef NDEBUG
  GTEST_SKIP() << "two continuation solves: optimised builds only";
#endif
  const StrikeSolve narrowed(0.15), wider(0.05);
  ASSERT_EQ(narrowed.solution.result.status, "Solve_Succeeded");
  ASSERT_EQ(wider.solution.result.status, "Solve_Succeeded");
  const double mu = wider.model.friction();
  const Vec2d in_narrowed = narrowed.impulseRatios(), in_wider = wider.impulseRatios();
  RecordProperty("cost_narrowed", fmt::format("{:.3f}", narrowed.solution.result.cost));
  RecordProperty("cost_wider", fmt::format("{:.3f}", wider.solution.result.cost));
  RecordProperty("trailing_ratio_wider", fmt::format("{:.4f}", in_wider.y()));
  // Each keeps its own cone, and the wider one is used: the trailing impulse is the one that
  // binds the strike (a scale-free condition: it binds however gentle the strike is).
  EXPECT_LE(in_narrowed.maxCoeff(), mu - 0.15 + 1e-6);
  EXPECT_LE(in_wider.maxCoeff(), mu - 0.05 + 1e-6);
  EXPECT_GT(in_wider.y(), mu - 0.15 + 0.05);
  EXPECT_LT(wider.solution.result.cost, 0.95 * narrowed.solution.result.cost);
  // The plants' impact law agrees with the NLP's impulses: both tips stick (to rounding on the
  // cone's edge) and the ground pushes at both.
  for (const StrikeSolve* s : {&narrowed, &wider}) {
    const dynamics::FrictionalImpact impact = s->plantImpact();
    EXPECT_TRUE(impact.unilateral_ok);
    EXPECT_TRUE(impact.consistent);
    EXPECT_LT(impact.trailing.velocity.norm(), 1e-4);
    EXPECT_LT(impact.leading.velocity.norm(), 1e-4);
    EXPECT_GT(impact.trailing.impulse.y(), 0.0);
  }
}

}  // namespace
}  // namespace gaitopt::ocp
