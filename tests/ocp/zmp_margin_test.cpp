// constraints.zmp_margin (OcpConfig::zmp_margin): strict reading against the robot's foot, and
// a solve whose ZMP, and in the DSP the torque-carrying foot B's own centre of pressure, are
// recomputed here from the solution's forces and ankle torque (gaits::zmpX, x_B = -tau0 / F_By)
// and keep the margin from the ends of the support. A foot that rotates about its edge ends a
// tracked walk (docs/closed_loop.md), so the margin is room for the controller's feedback.
#include <gtest/gtest.h>

#include <algorithm>

#include <fmt/format.h>

#include "gaits/export/metrics.hpp"
#include "ocp/problem/gait_problem.hpp"
#include "support/edited_config.hpp"
#include "support/solved_config.hpp"

namespace gaitopt::ocp {
namespace {

const std::string kMarginConfig = test::shippedOcpConfig("mu2004_walk");
constexpr double kMargin = 0.07;  // [m]; the default optimum keeps 0.0497 m, so this binds

TEST(ZmpMarginConfig, NegativeOrNoFootLeftOrWithoutZmpAreErrorsNamingTheKey) {
  const std::string fm = "friction_margin: 0.15";
  EXPECT_EQ(test::loadEditedOcpConfig(kMarginConfig, fm, fm + "\n  zmp_margin: 0.05"), "");
  const std::string negative =
      test::loadEditedOcpConfig(kMarginConfig, fm, fm + "\n  zmp_margin: -0.01");
  EXPECT_NE(negative.find("key 'constraints.zmp_margin'"), std::string::npos) << negative;
  // The shipped foot is 0.05 m of heel and 0.15 m of toe: half of it is 0.1 m.
  const std::string half = test::loadEditedOcpConfig(kMarginConfig, fm, fm + "\n  zmp_margin: 0.1");
  EXPECT_NE(half.find("key 'constraints.zmp_margin': expected less than half the robot's foot, "
                      "(heel 0.05 + toe 0.15) / 2 = 0.1 m, got 0.1 m"),
            std::string::npos)
      << half;
  const std::string no_zmp =
      test::loadEditedOcpConfig(kMarginConfig, "zmp: true", "zmp: false\n  zmp_margin: 0.02");
  EXPECT_NE(no_zmp.find("key 'constraints.zmp_margin': a ZMP margin needs zmp: true"),
            std::string::npos)
      << no_zmp;
}

TEST(ZmpMarginConfig, AMarginSetInCodeThatLeavesNoFootThrows) {
  OcpConfig c = loadOcpConfig(kMarginConfig);
  const dynamics::Model model = problemModel(c);
  c.zmp_margin = 0.02;
  EXPECT_DOUBLE_EQ(marginFoot(model, c).heel, 0.03);
  EXPECT_DOUBLE_EQ(marginFoot(model, c).toe, 0.13);
  c.zmp_margin = 0.1;
  EXPECT_THROW(marginFoot(model, c), std::invalid_argument);
}

/// Least distance [m] over the knots of the ZMP to the ends of the support (the foot in the
/// SSP, the hull of both in the DSP) and, in the DSP, of foot B's centre of pressure
/// x_B = -tau0 / F_By (the ground moment on the robot is -tau0) to the ends of foot B.
double leastSupportMargin(const gaits::Trajectory& traj, const dynamics::Model& model) {
  double least = gaits::minZmpMargin(traj, model);
  for (const auto& k : traj.knots()) {
    if (k.phase != gaits::Phase::kDsp) continue;
    const double x_b = -k.tau(0) / k.force_stance.y();
    least = std::min({least, x_b + model.foot().heel, model.foot().toe - x_b});
  }
  return least;
}

TEST(ZmpMargin, KeepsTheZmpAndFootBsCentreOfPressureThatFarInside) {
#ifndef NDEBUG
  GTEST_SKIP() << "two solves: optimised builds only";
#endif
  // The DSP collocated in theta on equal segments: there its forces vary least between the
  // points. In the default's reduced coordinates foot B's centre of pressure swings by up to 4 cm
  // between the first DSP points (results/dsp_coordinates.md), so the margin holds at the points
  // and the export contract's foot (tests/ocp/five_link_problem_test.cpp) between them.
  OcpConfig c = loadOcpConfig(kMarginConfig);
  c.dsp_reduced_coordinates = false;
  c.phases.back().first_segment = 0;
  const test::SolvedConfig free(c);
  c.zmp_margin = kMargin;
  const test::SolvedConfig held(c);
  ASSERT_EQ(free.result.status, "Solve_Succeeded");
  ASSERT_EQ(held.result.status, "Solve_Succeeded");
  const double at_free =
      leastSupportMargin(reconstruct(free.problem, free.model, free.result.x), free.model);
  const double at_knots =
      leastSupportMargin(reconstruct(held.problem, held.model, held.result.x), held.model);
  const double dense = leastSupportMargin(
      reconstructDense(held.problem, held.model, held.result.x, 1000), held.model);
  RecordProperty("least_margin_without_m", fmt::format("{:.5f}", at_free));
  RecordProperty("least_margin_knots_m", fmt::format("{:.6f}", at_knots));
  RecordProperty("least_margin_1khz_m", fmt::format("{:.6f}", dense));
  RecordProperty("cost_without", fmt::format("{:.3f}", free.result.cost));
  RecordProperty("cost_with", fmt::format("{:.3f}", held.result.cost));
  EXPECT_LT(at_free, kMargin);                    // without it the optimum goes nearer the edge,
  EXPECT_NEAR(at_knots, kMargin, 1e-6);           // with it the margin binds at the knots,
  EXPECT_GT(dense, kMargin - 1e-3);               // holds between them to 1 mm,
  EXPECT_GT(held.result.cost, free.result.cost);  // and costs torque
}

}  // namespace
}  // namespace gaitopt::ocp
