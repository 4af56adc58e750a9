// Ground reaction and ZMP: the momentum-based ZMP equals the centre of pressure of the contact
// forces and the ankle moment, which come from a different computation (forward dynamics).
#include <numbers>

#include <gtest/gtest.h>

#include "dynamics/centre_of_pressure.hpp"
#include "dynamics/dsp_dynamics.hpp"
#include "dynamics/ground.hpp"
#include "dynamics/model_variation.hpp"
#include "dynamics/ssp_dynamics.hpp"
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

TEST_P(GroundTest, OnASlopeTheWorldVerticalPostureStandsWithoutTorque) {
  // Ground frame, gravity rotated (model.hpp). Every link vertical in the world, theta_i = gamma
  // (swing links gamma + pi, hanging down): G_i = -g_i sin(theta_i - gamma) = 0, so standing
  // still needs no joint torque, the ground carries the weight m g (sin gamma, cos gamma) and the
  // ZMP is at B, under the CoM along the world vertical.
  const int n = model_.nLinks();
  const VecD zero = VecD::Zero(n);
  for (const double gamma : {0.1, -0.2}) {
    const dynamics::Model sloped = dynamics::withSlope(model_, gamma);
    VecD theta = VecD::Constant(n, gamma);
    for (int i = n - model_.legLinks(); i < n; ++i) theta(i) += std::numbers::pi;
    const double weight = model_.totalMass() * model_.gravity();
    EXPECT_LT(dynamics::sspInverseDynamics(sloped, theta, zero, zero).cwiseAbs().maxCoeff(),
              1e-12 * weight);
    const Vec2d f = dynamics::stanceForce(sloped, theta, zero, zero, Vec2d(Vec2d::Zero()));
    EXPECT_NEAR(f(0), weight * std::sin(gamma), 1e-12 * weight);
    EXPECT_NEAR(f(1), weight * std::cos(gamma), 1e-12 * weight);
    EXPECT_NEAR(dynamics::zeroMomentPoint(sloped, theta, zero, zero), 0.0, 1e-12);
    // Upright in the ground frame (theta = 0) is not a rest posture on the slope: gravity pulls
    // every link downhill, G_i = g_i sin(gamma).
    VecD upright = VecD::Zero(n);
    for (int i = n - model_.legLinks(); i < n; ++i) upright(i) = std::numbers::pi;
    const VecD g_upright = dynamics::gravityVector(sloped, upright);
    for (int i = 0; i < n - model_.legLinks(); ++i)
      EXPECT_NEAR(g_upright(i), model_.gravityCoefficients()(i) * std::sin(gamma), 1e-9);
    EXPECT_GT(dynamics::sspInverseDynamics(sloped, upright, zero, zero).cwiseAbs().maxCoeff(),
              0.01 * weight * model_.hipWeights().sum() * std::abs(gamma));
  }
}

TEST_P(GroundTest, OnASlopeZmpAndStanceForceMatchCentreOfPressureAndFloatingBase) {
  // The same identities as on level ground, with gravity rotated in both computations.
  const dynamics::Model sloped = dynamics::withSlope(model_, 0.15);
  const int n = model_.nLinks();
  int checked = 0;
  for (int trial = 0; trial < 50; ++trial) {
    const VecD theta = randomPosture(rng_, sloped);
    const VecD dtheta = randomVec(rng_, n, -1, 1);
    const VecD tau = randomVec(rng_, n, -20, 20);
    const VecD ddtheta = dynamics::sspForwardDynamics(sloped, theta, dtheta, tau);
    const Vec2d f_b = dynamics::stanceForce(sloped, theta, dtheta, ddtheta, Vec2d(Vec2d::Zero()));
    const FloatingBase fb = floatingBase(sloped, theta, dtheta);
    const auto [qdd, f] =
        solveKkt(fb.mass, actuation(sloped, tau) - fb.bias, fb.jac_b, Eigen::VectorXd::Zero(2));
    EXPECT_LT(relErr(VecD(qdd.tail(n)), ddtheta, 1.0), 1e-9);
    EXPECT_LT(relErr(f_b, Vec2d(f), 1.0), 1e-9);
    if (f_b(1) < 1.0) continue;
    const double cop = dynamics::centreOfPressure(0.0, f_b, -tau(0), 0.0, Vec2d(Vec2d::Zero()));
    EXPECT_NEAR(dynamics::zeroMomentPoint(sloped, theta, dtheta, ddtheta), cop,
                1e-9 * (1 + std::abs(cop)));
    ++checked;
  }
  EXPECT_GT(checked, 10);
}

INSTANTIATE_TEST_SUITE_P(AllRobots, GroundTest, ::testing::ValuesIn(allRobots()));

}  // namespace
}  // namespace gaitopt::test
