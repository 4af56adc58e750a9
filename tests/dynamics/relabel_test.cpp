// Relabelling (Mu 2.38, corrected) and the joint-coordinate maps (2.41-2.44).
#include <numbers>

#include <gtest/gtest.h>

#include "dynamics/energy.hpp"
#include "dynamics/impact/relabel.hpp"
#include "dynamics/joint_coordinates.hpp"
#include "dynamics/kinematics.hpp"
#include "dynamics/ssp_dynamics.hpp"
#include "support/fixtures.hpp"

namespace gaitopt::test {
namespace {

class RelabelTest : public ::testing::TestWithParam<std::string> {
 protected:
  dynamics::Model model_ = loadNamed(GetParam());
  std::mt19937 rng_{5};
};

TEST_P(RelabelTest, RelabelTwiceIsTheIdentity) {
  for (int trial = 0; trial < 100; ++trial) {
    const VecD theta = randomPosture(rng_, model_);
    const VecD dtheta = randomVec(rng_, model_.nLinks(), -3, 3);
    const VecD twice = dynamics::relabelAngles(model_, dynamics::relabelAngles(model_, theta));
    EXPECT_LT((twice - theta).norm(), 1e-14);
    EXPECT_EQ(dynamics::relabelRates(dynamics::relabelRates(dtheta)), dtheta);
  }
}

TEST_P(RelabelTest, RelabelKeepsTheRobotWhereItIs) {
  // The physical robot does not move: seen from the new stance tip (the old E), every link CoM
  // is where it was, the torso keeps its angle, and kinetic energy is unchanged.
  const int n = model_.nLinks();
  for (int trial = 0; trial < 100; ++trial) {
    const VecD theta = randomPosture(rng_, model_);
    const VecD dtheta = randomVec(rng_, n, -3, 3);
    const VecD th_new = dynamics::relabelAngles(model_, theta);
    const VecD dth_new = dynamics::relabelRates(dtheta);
    const Vec2d old_e = dynamics::swingTip(model_, theta);
    for (int i = 0; i < n; ++i) {
      const Vec2d before = dynamics::pointPosition(model_.comWeights(i), theta);
      const Vec2d after = old_e + dynamics::pointPosition(model_.comWeights(n - 1 - i), th_new);
      EXPECT_LT((after - before).norm(), 1e-12) << "link " << i;
    }
    if (model_.torso()) {
      EXPECT_DOUBLE_EQ(th_new(*model_.torso()), theta(*model_.torso()));
    }
    // Kinetic energy is frame independent; the old E moves at Xdot_e, so compare with the base
    // velocity of the new chain set to that tip velocity.
    const Vec2d v_e = dynamics::pointJacobian(model_.tipWeights(), theta) * dtheta;
    EXPECT_NEAR(dynamics::kineticEnergy<double>(model_, th_new, dth_new, v_e),
                dynamics::kineticEnergy<double>(model_, theta, dtheta), 1e-10);
  }
}

TEST_P(RelabelTest, JointCoordinatesAreInverseAndPreserveVirtualWork) {
  const int n = model_.nLinks();
  const MatD m = dynamics::jointMap(n);
  for (int trial = 0; trial < 100; ++trial) {
    const VecD theta = randomVec(rng_, n, -std::numbers::pi, std::numbers::pi);
    const VecD q = dynamics::toJoint(theta);
    EXPECT_LT((q - m * theta).norm(), 1e-15);
    EXPECT_LT((dynamics::toAbsolute(q) - theta).norm(), 1e-14);
    const VecD tau = randomVec(rng_, n, -50, 50);
    const VecD t_theta = dynamics::generalizedTorque(tau);
    EXPECT_LT((t_theta - m.transpose() * tau).norm(), 1e-12);
    EXPECT_LT((dynamics::jointTorque(t_theta) - tau).norm(), 1e-12);
    // Virtual work T_theta . dtheta = tau . dq (Mu 2.42).
    const VecD dtheta = randomVec(rng_, n, -1, 1);
    EXPECT_NEAR(t_theta.dot(dtheta), tau.dot(dynamics::toJoint(dtheta)), 1e-10);
  }
}

TEST_P(RelabelTest, JointSpaceMassMatrixGivesTheSameKineticEnergy) {
  // D_q = M^-T D M^-1 (Mu 2.44a): 1/2 dq^T D_q dq = 1/2 dtheta^T D dtheta with dq = M dtheta.
  for (int trial = 0; trial < 20; ++trial) {
    const VecD theta = randomPosture(rng_, model_);
    const VecD dtheta = randomVec(rng_, model_.nLinks(), -3, 3);
    const VecD dq = dynamics::toJoint(dtheta);
    const MatD d_q = dynamics::jointSpaceMassMatrix(dynamics::massMatrix(model_, theta));
    EXPECT_NEAR(0.5 * dq.dot(d_q * dq), dynamics::kineticEnergy<double>(model_, theta, dtheta),
                1e-10);
  }
}

INSTANTIATE_TEST_SUITE_P(AllRobots, RelabelTest, ::testing::ValuesIn(allRobots()));

TEST(JointCoordinates, StanceKneeTorqueActsOnShankAndThigh) {
  // Mu sec. 9 fact 6: a pure stance-knee torque gives T_theta = (tau1, -tau1, 0, 0, 0).
  VecD tau = VecD::Zero(5);
  tau(1) = 7.0;
  const VecD t = dynamics::generalizedTorque(tau);
  EXPECT_EQ(t, (VecD(5) << 7, -7, 0, 0, 0).finished());
}

}  // namespace
}  // namespace gaitopt::test
