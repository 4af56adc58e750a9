// D, H, G of Mu (2.8) against the numeric Lagrangian, on every shipped robot.
#include <numbers>

#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include "dynamics/model_variation.hpp"
#include "dynamics/ssp_dynamics.hpp"
#include "support/fixtures.hpp"
#include "support/numeric_lagrangian.hpp"

namespace gaitopt::test {
namespace {

using dynamics::Model;

class LagrangianTest : public ::testing::TestWithParam<std::string> {
 protected:
  Model model_ = loadNamed(GetParam());
  std::mt19937 rng_{42};
};

TEST_P(LagrangianTest, MassMatrixIsSymmetricPositiveDefinite) {
  for (int trial = 0; trial < 200; ++trial) {
    const VecD theta = randomVec(rng_, model_.nLinks(), -std::numbers::pi, std::numbers::pi);
    const MatD d = dynamics::massMatrix(model_, theta);
    EXPECT_EQ((d - d.transpose()).norm(), 0.0);
    const double min_eig = Eigen::SelfAdjointEigenSolver<MatD>(d).eigenvalues().minCoeff();
    EXPECT_GT(min_eig, 1e-6) << "trial " << trial;
  }
}

TEST_P(LagrangianTest, MassMatrixEqualsNumericLagrangian) {
  for (int trial = 0; trial < 50; ++trial) {
    const VecD theta = randomVec(rng_, model_.nLinks(), -std::numbers::pi, std::numbers::pi);
    EXPECT_LT(relErr(dynamics::massMatrix(model_, theta), numericMassMatrix(model_, theta)), 1e-9);
  }
}

TEST_P(LagrangianTest, CoriolisEqualsNumericLagrangian) {
  for (int trial = 0; trial < 50; ++trial) {
    const VecD theta = randomVec(rng_, model_.nLinks(), -std::numbers::pi, std::numbers::pi);
    const VecD dtheta = randomVec(rng_, model_.nLinks(), -5, 5);
    EXPECT_LT(
        relErr(dynamics::coriolis(model_, theta, dtheta), numericCoriolis(model_, theta, dtheta)),
        1e-9);
  }
}

TEST_P(LagrangianTest, GravityEqualsNumericLagrangianAndCatchesPrintedSign) {
  for (int trial = 0; trial < 50; ++trial) {
    const VecD theta = randomVec(rng_, model_.nLinks(), -std::numbers::pi, std::numbers::pi);
    const VecD numeric = numericGravity(model_, theta);
    EXPECT_LT(relErr(dynamics::gravityVector(model_, theta), numeric), 1e-9);
    // Mu (2.8c) as printed, G_i = +g_i sin(theta_i), is the negative: the test must reject it.
    VecD printed(model_.nLinks());
    for (int i = 0; i < model_.nLinks(); ++i)
      printed(i) = model_.gravityCoefficients()(i) * std::sin(theta(i));
    EXPECT_GT(relErr(printed, numeric), 1.0);
  }
}

TEST_P(LagrangianTest, GravityOnASlopeEqualsNumericLagrangianOfTheRotatedPotential) {
  // Mu (2.8c) with gravity rotated by the slope: G_i = -g_i sin(theta_i - gamma), against the
  // derivative of P = -sum m_i g_vec . r_ci (energy.hpp, from CoM positions, not from g_i).
  for (const double slope : {0.2, -0.3}) {
    const Model sloped = dynamics::withSlope(model_, slope);
    for (int trial = 0; trial < 20; ++trial) {
      const VecD theta = randomVec(rng_, model_.nLinks(), -std::numbers::pi, std::numbers::pi);
      const VecD numeric = numericGravity(sloped, theta);
      EXPECT_LT(relErr(dynamics::gravityVector(sloped, theta), numeric), 1e-9) << slope;
      // The level-ground G is not the answer: the slope must matter.
      EXPECT_GT(relErr(dynamics::gravityVector(model_, theta), numeric), 0.01) << slope;
    }
  }
}

TEST_P(LagrangianTest, CoriolisPowerIsHalfDdotPower) {
  // Ddot - 2C is skew (Mu 4.7), so dtheta^T Ddot dtheta = 2 dtheta^T H dtheta.
  for (int trial = 0; trial < 20; ++trial) {
    const VecD theta = randomVec(rng_, model_.nLinks(), -std::numbers::pi, std::numbers::pi);
    const VecD dtheta = randomVec(rng_, model_.nLinks(), -3, 3);
    const double h = 1e-6;
    const MatD ddot = (dynamics::massMatrix<double>(model_, theta + h * dtheta) -
                       dynamics::massMatrix<double>(model_, theta - h * dtheta)) /
                      (2 * h);
    const double ddot_power = dtheta.dot(ddot * dtheta);
    const double h_power = dtheta.dot(dynamics::coriolis(model_, theta, dtheta));
    EXPECT_NEAR(ddot_power, 2 * h_power, 1e-8 * (1 + std::abs(ddot_power)));
  }
}

INSTANTIATE_TEST_SUITE_P(AllRobots, LagrangianTest, ::testing::ValuesIn(allRobots()));

}  // namespace
}  // namespace gaitopt::test
