// Ground reaction and ZMP: the momentum-based ZMP equals the centre of pressure of the contact
// forces and the ankle moment, which come from a different computation (forward dynamics).
#include <gtest/gtest.h>

#include "dynamics/dsp_dynamics.hpp"
#include "dynamics/ground.hpp"
#include "support/fixtures.hpp"
#include "support/floating_base.hpp"

namespace gaitopt::test {
namespace {

class GroundTest : public ::testing::TestWithParam<std::string> {
 protected:
  dynamics::Model model_ = loadNamed(GetParam());
  std::mt19937 rng_{9};
};

TEST_P(GroundTest, SspZmpEqualsCentreOfPressureOfAnkleMoment) {
  const int n = model_.nLinks();
  int checked = 0;
  for (int trial = 0; trial < 100; ++trial) {
    const VecD theta = randomPosture(rng_, model_);
    const VecD dtheta = randomVec(rng_, n, -1, 1);
    const VecD tau = randomVec(rng_, n, -20, 20);
    const VecD ddtheta = dynamics::sspForwardDynamics(model_, theta, dtheta, tau);
    const Vec2d f_b = dynamics::stanceForce(model_, theta, dtheta, ddtheta, Vec2d(Vec2d::Zero()));
    if (f_b(1) < 1.0) continue;  // the ZMP is undefined without a normal force
    // Ground moment on the robot at B is -tau0 (conventions.hpp).
    const double cop = dynamics::centreOfPressure(0.0, f_b, -tau(0), 0.0, Vec2d(Vec2d::Zero()));
    const double zmp = dynamics::zeroMomentPoint(model_, theta, dtheta, ddtheta);
    EXPECT_NEAR(zmp, cop, 1e-9 * (1 + std::abs(cop)));
    ++checked;
  }
  EXPECT_GT(checked, 20);
}

TEST_P(GroundTest, SspStanceForceMatchesFloatingBase) {
  const int n = model_.nLinks();
  for (int trial = 0; trial < 50; ++trial) {
    const VecD theta = randomPosture(rng_, model_);
    const VecD dtheta = randomVec(rng_, n, -1, 1);
    const VecD tau = randomVec(rng_, n, -20, 20);
    const VecD ddtheta = dynamics::sspForwardDynamics(model_, theta, dtheta, tau);
    const FloatingBase fb = floatingBase(model_, theta, dtheta);
    const auto [qdd, f] =
        solveKkt(fb.mass, actuation(model_, tau) - fb.bias, fb.jac_b, Eigen::VectorXd::Zero(2));
    EXPECT_LT(relErr(VecD(qdd.tail(n)), ddtheta, 1.0), 1e-9);
    EXPECT_LT(relErr(dynamics::stanceForce(model_, theta, dtheta, ddtheta, Vec2d(Vec2d::Zero())),
                     Vec2d(f), 1.0),
              1e-9);
  }
}

TEST_P(GroundTest, StandingStillZmpIsUnderTheCom) {
  const int n = model_.nLinks();
  const VecD theta = randomPosture(rng_, model_);
  const VecD zero = VecD::Zero(n);
  EXPECT_NEAR(dynamics::zeroMomentPoint(model_, theta, zero, zero),
              dynamics::centreOfMass(model_, theta)(0), 1e-12);
}

INSTANTIATE_TEST_SUITE_P(AllRobots, GroundTest, ::testing::ValuesIn(allRobots()));

}  // namespace
}  // namespace gaitopt::test
