// Mu's parameter uncertainty (ch. 4) as a plant variant: every coefficient of the dynamics scales
// as its units say (p_ij ~ m l^2, g_i ~ m l g), the total mass by (1 + e_m), and nothing else
// changes.
#include <numbers>

#include <gtest/gtest.h>

#include "dynamics/model_variation.hpp"
#include "dynamics/robot_files/robot_config.hpp"

namespace gaitopt::dynamics {
namespace {

const std::string kRobot =
    std::string(GAITOPT_SOURCE_DIR) + "/configs/robots/mu2004_five_link.yaml";

TEST(ModelVariation, GeometricScalingScalesTheDynamicsCoefficientsByTheirUnits) {
  const Model nominal = loadRobot(kRobot);
  const double a = 1.4, b = 1.1;  // masses by a, lengths by b, so inertias by a b^2
  const Model plant = perturbedModel(nominal, {a - 1, a * b * b - 1, b - 1, b - 1});
  EXPECT_NEAR(plant.totalMass(), a * nominal.totalMass(), 1e-12);
  // p_ij = I_i + m_i d_i^2 + ... and every m l d term scale by a b^2; g_i = (m d + ...) g by a b.
  const MatD p_expected = a * b * b * nominal.inertiaCoefficients();
  EXPECT_LT((plant.inertiaCoefficients() - p_expected).cwiseAbs().maxCoeff(),
            1e-12 * p_expected.cwiseAbs().maxCoeff());
  const VecD g_expected = a * b * nominal.gravityCoefficients();
  EXPECT_LT((plant.gravityCoefficients() - g_expected).cwiseAbs().maxCoeff(),
            1e-12 * g_expected.cwiseAbs().maxCoeff());
  EXPECT_NEAR(plant.tipWeights().sum(), b * nominal.tipWeights().sum(), 1e-12);
  EXPECT_EQ(plant.friction(), nominal.friction());
}

TEST(ModelVariation, MuCasesScaleMassAndInertiaAlikeAndLengthsAlike) {
  const Model nominal = loadRobot(kRobot);
  const Model plant = perturbedModel(nominal, muUncertaintyCase(3));
  for (int i = 0; i < nominal.nLinks(); ++i) {
    EXPECT_NEAR(plant.link(i).mass, 2.0 * nominal.link(i).mass, 1e-12);
    EXPECT_NEAR(plant.link(i).inertia, 2.0 * nominal.link(i).inertia, 1e-12);
    EXPECT_NEAR(plant.link(i).length, 1.4 * nominal.link(i).length, 1e-12);
    EXPECT_NEAR(plant.link(i).com, 1.4 * nominal.link(i).com, 1e-12);
  }
}

TEST(ModelVariation, FrictionVariantChangesOnlyFriction) {
  const Model nominal = loadRobot(kRobot);
  const Model plant = withFriction(nominal, 0.25);
  EXPECT_EQ(plant.friction(), 0.25);
  EXPECT_EQ(plant.inertiaCoefficients(), nominal.inertiaCoefficients());
  EXPECT_THROW(withFriction(nominal, -0.1), std::invalid_argument);
}

TEST(ModelVariation, SlopeVariantRotatesGravityOnly) {
  const Model nominal = loadRobot(kRobot);
  EXPECT_EQ(nominal.slope(), 0.0);
  EXPECT_EQ(nominal.gravityAcceleration(), Eigen::Vector2d(0, -nominal.gravity()));
  const Model sloped = withSlope(nominal, 0.1);
  EXPECT_EQ(sloped.slope(), 0.1);
  const double g = nominal.gravity();
  EXPECT_NEAR(sloped.gravityAcceleration()(0), -g * std::sin(0.1), 1e-15);
  EXPECT_NEAR(sloped.gravityAcceleration()(1), -g * std::cos(0.1), 1e-15);
  EXPECT_EQ(sloped.gravityCoefficients(), nominal.gravityCoefficients());
  EXPECT_EQ(sloped.inertiaCoefficients(), nominal.inertiaCoefficients());
  // The other variants keep the slope.
  EXPECT_EQ(withFriction(sloped, 0.3).slope(), 0.1);
  EXPECT_EQ(perturbedModel(sloped, muUncertaintyCase(2)).slope(), 0.1);
  EXPECT_THROW(withSlope(nominal, std::numbers::pi / 2), std::invalid_argument);
  EXPECT_THROW(withSlope(nominal, NAN), std::invalid_argument);
}

TEST(ModelVariation, RejectsImpossibleErrors) {
  const Model nominal = loadRobot(kRobot);
  EXPECT_THROW(perturbedModel(nominal, {-1.0, 0, 0, 0}), std::invalid_argument);
  EXPECT_THROW(perturbedModel(nominal, {0, 0, NAN, 0}), std::invalid_argument);
  EXPECT_THROW(muUncertaintyCase(4), std::invalid_argument);
}

}  // namespace
}  // namespace gaitopt::dynamics
