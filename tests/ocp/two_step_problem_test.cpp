// Two steps in one period (ocp/shape/gait_shape.hpp, config key `steps`): the passive compass
// gait of configs/ocp/compass_gait_passive.yaml with the periodicity closed after the second
// step, each step its own single support, impact and relabelling. Down the slope of 0.05 rad the
// period-1 passive gait is the gait (McGeer 1990; Goswami et al. 1998 find it stable there and
// period-doubling only on steeper slopes), so the period-2 optimum must be two identical
// passive steps: zero torque, the same duration (Newton shooting on the stride map gives
// 0.621817212397 s, the config's comment), the same states point by point. The second step is
// started from a different guess (a 0.5 s step) so that the equality is the solver's finding.
#include <gtest/gtest.h>

#include <cmath>

#include <fmt/format.h>

#include "ocp/guess/initial_guess.hpp"
#include "ocp/problem/gait_problem.hpp"
#include "ocp/shape/gait_shape.hpp"
#include "ocp/shape/shape_builder.hpp"
#include "ocp/solve/ipopt_adapter.hpp"
#include "support/solved_config.hpp"

namespace gaitopt::ocp {
namespace {

constexpr double kPassiveStep = 0.621817212397;  // [s]
constexpr double kSecondGuess = 0.5;             // [s]

TEST(TwoStepPassiveGait, CollapsesToTwoIdenticalPassiveSteps) {
#ifndef NDEBUG
  GTEST_SKIP() << "a solve: optimised builds only";
#endif
  OcpConfig c = loadOcpConfig(test::shippedOcpConfig("compass_gait_passive"),
                              {config::parseOverride("steps=2")});
  ASSERT_EQ(c.shape.steps, 2);
  const dynamics::Model model = problemModel(c);
  GaitShape shape = describeGait(model, c);
  ASSERT_EQ(shape.phases.size(), 2u);
  OcpConfig second = c;
  second.phases.front().duration = shape.phases[1].mesh.duration = kSecondGuess;
  const GaitProblem p =
      assembleGaitProblem(shape, c, {initialGuess(model, c), initialGuess(model, second)});
  const Phase& one = *p.phasesOf(0, 0).front();
  const Phase& two = *p.phasesOf(1, 0).front();
  ASSERT_NEAR(two.layout.durationAt(p.nlp.initialGuess()), kSecondGuess, 1e-12);

  const SolveResult r = solveWithIpopt(p.nlp, c.solver);
  ASSERT_TRUE(r.success) << r.status;
  RecordProperty("iterations", r.iterations);
  RecordProperty("cost", fmt::format("{:.3e}", r.cost));
  EXPECT_LT(r.cost, 1e-8);  // N^2 m^2 s: both steps passive
  const double t1 = one.layout.durationAt(r.x), t2 = two.layout.durationAt(r.x);
  EXPECT_NEAR(t1, t2, 1e-6);
  EXPECT_NEAR(t1, kPassiveStep, 1e-3);
  double gap = 0, peak = 0;
  for (int k = 0; k < one.layout.points(); ++k) {
    const Eigen::VectorXd a = one.layout.point(r.x, k), b = two.layout.point(r.x, k);
    gap = std::max(gap, (one.point.q.of(a) - two.point.q.of(b)).cwiseAbs().maxCoeff());
    gap = std::max(gap, (one.point.v.of(a) - two.point.v.of(b)).cwiseAbs().maxCoeff());
    peak = std::max(
        {peak, one.point.u.of(a).cwiseAbs().maxCoeff(), two.point.u.of(b).cwiseAbs().maxCoeff()});
  }
  RecordProperty("durations_s", fmt::format("{:.9f} {:.9f}", t1, t2));
  RecordProperty("largest_state_gap", fmt::format("{:.2e}", gap));
  EXPECT_LT(gap, 1e-6);   // rad, rad/s
  EXPECT_LT(peak, 1e-4);  // N m
  // The nominal's steps reconstruct in order, each a full step of the period's duration.
  const auto steps = reconstructSteps(p, model, r.x);
  ASSERT_EQ(steps.size(), 2u);
  EXPECT_NEAR(steps[0].endTime(), t1, 1e-12);
  EXPECT_NEAR(steps[1].endTime(), t2, 1e-12);
  EXPECT_LT((steps[0].knots().back().theta - steps[1].knots().back().theta).cwiseAbs().maxCoeff(),
            1e-6);
}

}  // namespace
}  // namespace gaitopt::ocp
