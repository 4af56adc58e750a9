// constraints.min_normal_force (OcpConfig::min_normal_force): read strictly, and a solve whose
// tips in contact (the stance tip in the SSP, both tips in the DSP) keep at least that normal
// force, read from the ground forces of the reconstructed solution at its knots and on the
// 1 kHz export. A tip loaded with nearly nothing lifts off at the least tracking error (issue
// "gaits robust by design": the default optimum's trailing tip carries 61 N before it lifts).
#include <gtest/gtest.h>

#include <algorithm>
#include <limits>

#include <fmt/format.h>

#include "ocp/problem/gait_problem.hpp"
#include "support/edited_config.hpp"
#include "support/solved_config.hpp"

namespace gaitopt::ocp {
namespace {

const std::string kForceConfig = test::shippedOcpConfig("mu2004_walk");
constexpr double kLeast = 100;  // [N]; the default optimum's least is about 61 N, so this binds

TEST(LeastNormalForceConfig, NegativeOrWithoutGroundContactAreErrorsNamingTheKey) {
  const std::string fm = "friction_margin: 0.15";
  EXPECT_EQ(test::loadEditedOcpConfig(kForceConfig, fm, fm + "\n  min_normal_force: 50"), "");
  const std::string negative =
      test::loadEditedOcpConfig(kForceConfig, fm, fm + "\n  min_normal_force: -1");
  EXPECT_NE(negative.find("key 'constraints.min_normal_force'"), std::string::npos) << negative;
  const std::string no_contact = test::loadEditedOcpConfig(
      kForceConfig, "ground_contact: true", "ground_contact: false\n  min_normal_force: 50");
  EXPECT_NE(no_contact.find("key 'constraints.min_normal_force': a least normal force needs "
                            "ground_contact: true"),
            std::string::npos)
      << no_contact;
}

/// The least normal force [N] over the knots on the tips in contact: B always, E in the DSP.
double leastNormalForce(const gaits::Trajectory& traj) {
  double least = std::numeric_limits<double>::infinity();
  for (const auto& k : traj.knots()) {
    least = std::min(least, k.force_stance.y());
    if (k.phase == gaits::Phase::kDsp) least = std::min(least, k.force_swing.y());
  }
  return least;
}

TEST(LeastNormalForce, EveryTipInContactKeepsItAtTheKnotsAndWithinFifteenPercentBetweenThem) {
#ifndef NDEBUG
  GTEST_SKIP() << "two solves: optimised builds only";
#endif
  const test::SolvedConfig free(loadOcpConfig(kForceConfig));
  OcpConfig c = loadOcpConfig(kForceConfig);
  c.min_normal_force = kLeast;
  const test::SolvedConfig held(c);
  ASSERT_EQ(free.result.status, "Solve_Succeeded");
  ASSERT_EQ(held.result.status, "Solve_Succeeded");
  const double at_free = leastNormalForce(reconstruct(free.problem, free.model, free.result.x));
  const double at_knots = leastNormalForce(reconstruct(held.problem, held.model, held.result.x));
  const double dense =
      leastNormalForce(reconstructDense(held.problem, held.model, held.result.x, 1000));
  RecordProperty("least_without_N", fmt::format("{:.3f}", at_free));
  RecordProperty("least_knots_N", fmt::format("{:.6f}", at_knots));
  RecordProperty("least_1khz_N", fmt::format("{:.6f}", dense));
  RecordProperty("cost_without", fmt::format("{:.4f}", free.result.cost));
  RecordProperty("cost_with", fmt::format("{:.4f}", held.result.cost));
  EXPECT_LT(at_free, kLeast - 10);      // without it a tip carries less,
  EXPECT_NEAR(at_knots, kLeast, 1e-4);  // with it the bound binds at the knots,
  // Between the knots it is the scheme's interpolation that holds it: the DSP's six segments
  // are 17 ms long, and in the first, after the impact, trailing tip B's force dips about 10 %.
  EXPECT_GT(dense, 0.85 * kLeast);
  EXPECT_GT(held.result.cost, free.result.cost);  // and costs torque
}

}  // namespace
}  // namespace gaitopt::ocp
