// Physical joint coordinates (gaits/trajectory/physical_joints.hpp): postures whose encoder
// readings are known, and the work they do equal to the work in Mu's coordinates.
#include <numbers>
#include <random>

#include <gtest/gtest.h>

#include "dynamics/joint_coordinates.hpp"
#include "gaits/trajectory/physical_joints.hpp"
#include "support/fixtures.hpp"

namespace gaitopt::test {
namespace {

constexpr double kPi = std::numbers::pi;

Eigen::VectorXd physicalAngles(const dynamics::Model& model, const VecD& theta) {
  return gaits::physicalValues(gaits::physicalJoints(model), dynamics::toJoint(theta), true);
}

TEST(PhysicalJoints, StandingStraightUnderAnUprightTorsoReadsZeroEverywhere) {
  const dynamics::Model model = loadNamed("mu2004_five_link");
  VecD theta(5);
  theta << 0, 0, 0, kPi, kPi;  // stance leg up, torso up, swing leg hanging
  EXPECT_LT(physicalAngles(model, theta).cwiseAbs().maxCoeff(), 1e-15);
}

TEST(PhysicalJoints, BothKneesFlexPositiveAndBothHipsFlexPositiveForward) {
  const dynamics::Model model = loadNamed("mu2004_five_link");
  // Stance: shank leaning forward 0.2 from the ankle, thigh upright (knee flexed 0.2, the shank
  // behind the thigh's line below the knee). Swing: thigh swung forward 0.3 (down angle 0.3),
  // shank hanging 0.4 behind it (down angle -0.1). Torso leaning forward 0.1.
  VecD theta(5);
  theta << 0.2, 0.0, 0.1, kPi - 0.3, kPi + 0.1;
  const Eigen::VectorXd p = physicalAngles(model, theta);
  EXPECT_NEAR(p(0), 0.2, 1e-15);        // left ankle: the stance shank from the vertical
  EXPECT_NEAR(p(1), 0.2, 1e-15);        // left knee
  EXPECT_NEAR(p(2), 0.1, 1e-15);        // left hip: torso forward of the upright thigh
  EXPECT_NEAR(p(3), 0.3 + 0.1, 1e-15);  // right hip: thigh 0.3 forward, torso 0.1 forward
  EXPECT_NEAR(p(4), 0.4, 1e-15);        // right knee
}

TEST(PhysicalJoints, TorquesDoTheSameWorkAsMusOnEveryRobot) {
  std::mt19937 rng(3);
  for (const auto& name : allRobots()) {
    const dynamics::Model model = loadNamed(name);
    const auto joints = gaits::physicalJoints(model);
    EXPECT_EQ(static_cast<int>(joints.size()), model.nLinks()) << name;
    const VecD dq = randomVec(rng, model.nLinks(), -3, 3),
               tau = randomVec(rng, model.nLinks(), -50, 50);
    const double power =
        gaits::physicalValues(joints, tau, false).dot(gaits::physicalValues(joints, dq, false));
    EXPECT_NEAR(power, tau.dot(dq), 1e-12 * (1 + std::abs(power))) << name;
  }
}

}  // namespace
}  // namespace gaitopt::test
