// Numbers of the five-link model against the values worked out from Mu's Table 3.1
// (docs/derivations.md#link-inertias, I_i = 0.033 kg m^2 for every link, and
// docs/derivations.md#the-initial-state).
#include <numbers>

#include <gtest/gtest.h>

#include "dynamics/kinematics.hpp"
#include "dynamics/ssp_dynamics.hpp"
#include "support/fixtures.hpp"

namespace gaitopt::test {
namespace {

TEST(ModelValues, InertiaAndGravityCoefficientsMatchTable31) {
  const auto model = loadNamed("mu2004_five_link");
  MatD p(5, 5);
  p << 3.152636, 2.649586, 1.384699, 0.339284, 0.105871,  //
      2.649586, 2.360924, 1.259576, 0.308626, 0.096305,   //
      1.384699, 1.259576, 1.209160, 0, 0,                 //
      0.339284, 0.308626, 0, 0.259385, 0.096305,          //
      0.105871, 0.096305, 0, 0.096305, 0.078601;
  EXPECT_LT((model.inertiaCoefficients() - p).cwiseAbs().maxCoeff(), 1e-6);
  VecD g(5);
  g << 93.960474, 78.290471, 40.915352, 10.025231, 3.128311;
  EXPECT_LT((model.gravityCoefficients() - g).cwiseAbs().maxCoeff(), 1e-6);
  EXPECT_NEAR(model.totalMass(), 29.81, 1e-12);
  EXPECT_EQ(model.legLinks(), 2);
  EXPECT_EQ(model.torso().value(), 2);
}

TEST(ModelValues, Table41PostureKinematicsAndGravity) {
  // Table 4.1 in degrees, swing leg converted to the ch. 2 convention (theta = pi - phi).
  const auto model = loadNamed("mu2004_five_link");
  VecD theta(5);
  theta << 1.18 * kDeg, -31.29 * kDeg, 0.0, 190.19 * kDeg, 208.14 * kDeg;
  const Vec2d hip = dynamics::hip(model, theta);
  const Vec2d tip = dynamics::swingTip(model, theta);
  const Vec2d com = dynamics::centreOfMass(model, theta);
  EXPECT_NEAR(hip(0), -0.15001, 2e-5);
  EXPECT_NEAR(hip(1), 0.59000, 2e-5);
  EXPECT_NEAR(tip(0), -0.36002, 2e-5);
  EXPECT_NEAR(tip(1), 0.00001, 2e-5);
  EXPECT_NEAR(com(0), -0.14354, 2e-5);
  EXPECT_NEAR(com(1), 0.64675, 2e-5);
  VecD g(5);
  g << -1.935, 40.662, 0, 1.774, 1.475;
  EXPECT_LT((dynamics::gravityVector(model, theta) - g).cwiseAbs().maxCoeff(), 2e-3);
}

TEST(ModelValues, UprightStandingIsAnUnstableEquilibrium) {
  // Mu sec. 9 fact 5: theta = (0, 0, 0, pi, pi) is an equilibrium; leaning forward falls forward.
  const auto model = loadNamed("mu2004_five_link");
  VecD theta(5);
  theta << 0, 0, 0, std::numbers::pi, std::numbers::pi;
  const VecD zero = VecD::Zero(5);
  EXPECT_LT(dynamics::gravityVector(model, theta).norm(), 1e-12);
  EXPECT_LT(dynamics::sspForwardDynamics(model, theta, zero, zero).norm(), 1e-12);
  theta(0) = 0.01;
  EXPECT_GT(dynamics::sspForwardDynamics(model, theta, zero, zero)(0), 0.0);
}

}  // namespace
}  // namespace gaitopt::test
