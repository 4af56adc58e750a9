// The export contract (gaits/export/export_contract.hpp): which figures of a dense export break
// their bounds, on trajectories whose figures are known by construction.
#include <numbers>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "gaits/export/export_contract.hpp"
#include "support/fixtures.hpp"

namespace gaitopt::test {
namespace {

using gaits::Knot;
using gaits::Trajectory;

/// A robot standing still, feet together: the stance leg and the torso upright (theta = 0), the
/// swing leg hanging (theta = pi, docs/design.md#conventions), so the swing tip is on the ground at
/// the stance tip. `rate` Hz over 0.1 s of SSP, the stance tip carrying `force` and the ankle
/// `ankle_torque`.
Trajectory standing(double rate, const Vec2d& force, double ankle_torque = 0) {
  std::vector<Knot> knots;
  for (int j = 0; j <= static_cast<int>(0.1 * rate); ++j) {
    Knot k;
    k.t = j / rate;
    k.theta = k.dtheta = k.ddtheta = k.tau = Eigen::VectorXd::Zero(5);
    k.theta.tail(2).setConstant(std::numbers::pi);
    k.tau(0) = ankle_torque;
    k.force_stance = force;
    knots.push_back(k);
  }
  return Trajectory("test", 0.35, knots);
}

std::vector<std::string> checks(const Trajectory& traj, double rate) {
  std::vector<std::string> names;
  const dynamics::Model model = loadNamed("mu2004_five_link");
  for (const auto& b :
       gaits::exportBreaches(gaits::exportFigures(traj, model), model.friction(), rate))
    names.push_back(b.check);
  return names;
}

TEST(ExportContract, AStandingRobotOnItsFootKeepsEveryBound) {
  EXPECT_TRUE(checks(standing(1000, {0, 300}), 1000).empty());
}

// The robot file's actuator limits (10 rad/s and 150 N m at each joint of this robot), passed
// by more than kLimitTolerance: the default optimum's swing knee turned at 13.6 rad/s unseen.
TEST(ExportContract, AJointFasterOrStrongerThanItsActuatorBreaksItsLimit) {
  Trajectory traj = standing(200, {0, 300});  // 200 Hz: the derivative checks are not judged
  std::vector<Knot> knots = traj.knots();
  knots[3].dtheta(2) = -10.05;  // joint rates dq_2 = 10.05, dq_3 = -10.05: within 1 %
  EXPECT_TRUE(checks(Trajectory("test", 0.35, knots), 200).empty());
  knots[3].dtheta(2) = -10.5;
  EXPECT_EQ(checks(Trajectory("test", 0.35, knots), 200),
            std::vector<std::string>{"max_joint_rate_use"});
  knots[3].dtheta(2) = 0;
  knots[5].tau(3) = -157.5;  // the swing hip, 5 % over
  EXPECT_EQ(checks(Trajectory("test", 0.35, knots), 200),
            std::vector<std::string>{"max_torque_use"});
  const dynamics::Model model = loadNamed("mu2004_five_link");
  EXPECT_NEAR(gaits::exportFigures(Trajectory("test", 0.35, knots), model).max_torque_use, 1.05,
              1e-12);
}

TEST(ExportContract, AForceOutsideTheRobotsConeIsASlipNotTheConfigsMargin) {
  const dynamics::Model model = loadNamed("mu2004_five_link");
  const double mu = model.friction();  // 0.6; a config's friction margin does not count here
  EXPECT_TRUE(checks(standing(1000, {0.99 * mu * 300, 300}), 1000).empty());
  const auto breaches = gaits::exportBreaches(
      gaits::exportFigures(standing(1000, {1.01 * mu * 300, 300}), model), mu, 1000);
  ASSERT_EQ(breaches.size(), 1u);
  EXPECT_EQ(breaches[0].check, "max_friction_ratio");
  EXPECT_NEAR(breaches[0].value, 1.01 * mu, 1e-12);
  EXPECT_EQ(breaches[0].bound, mu);
}

TEST(ExportContract, APullOnTheGroundIsReportedInsteadOfItsConeAndCentreOfPressure) {
  // F_y < 0: the friction ratio and the CoP -tau0 / F_y mean nothing; only the pull is reported.
  EXPECT_EQ(checks(standing(1000, {100, -5}, 3.0), 1000),
            std::vector<std::string>{"min_normal_force"});
}

TEST(ExportContract, ACentreOfPressureBeyondTheHeelRollsTheFoot) {
  const dynamics::Model model = loadNamed("mu2004_five_link");
  // x_B = -tau0 / F_y: 1 mm behind the heel, then 0.5 micrometre (inside the tolerance).
  const double mm = 1e-3;
  EXPECT_EQ(checks(standing(1000, {0, 300}, (model.foot().heel + mm) * 300), 1000),
            std::vector<std::string>{"min_foot_cop_margin"});
  EXPECT_TRUE(
      checks(standing(1000, {0, 300}, (model.foot().heel + 5e-4 * mm) * 300), 1000).empty());
}

TEST(ExportContract, DerivativesAreJudgedOnlyOnExportsFineEnoughForTheirDifferences) {
  Trajectory traj = standing(1000, {0, 300});
  std::vector<Knot> knots = traj.knots();
  for (Knot& k : knots) k.dtheta(2) = 0.1;  // a rate whose angle never moves
  const Trajectory moving("test", 0.35, knots);
  EXPECT_EQ(checks(moving, 1000), std::vector<std::string>{"max_rate_mismatch"});
  EXPECT_TRUE(checks(moving, 200).empty());  // below kDerivativeCheckRateHz: not judged
  EXPECT_EQ(gaits::unjudgedChecks(200),
            (std::vector<std::string>{"max_rate_mismatch", "max_acceleration_mismatch"}));
  EXPECT_TRUE(gaits::unjudgedChecks(gaits::kDerivativeCheckRateHz).empty());
}

}  // namespace
}  // namespace gaitopt::test
