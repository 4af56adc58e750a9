// Scenarios: every sweep parameter sets what it names and reads back; Mu's uncertainty lands on
// the plant or on the controller's model as asked; a stiffness sweep needs a compliant ground
// (impedance, pad).
#include <gtest/gtest.h>

#include "sim/scenario/scenario.hpp"
#include "tests/sim/five_link_gait.hpp"

namespace gaitopt::sim {
namespace {

TEST(Scenario, EverySweepParameterReadsBackWhatItSets) {
  Scenario s;
  s.ground = CompliantGround{{1e7, 4.5e7, 1.5, 5e5, 2e3, 0.6}, 2e-4};
  for (const auto& p : sweepParameters()) {
    const double value = 0.5 * (p.first + p.last);
    setSweepValue(s, p.name(), value);
    EXPECT_EQ(sweepValue(s, p.name()), value) << p.name();
  }
  EXPECT_EQ(s.parameter_errors.inertia, s.parameter_errors.mass);
  EXPECT_EQ(s.parameter_errors.com, s.parameter_errors.length);
  ASSERT_TRUE(s.push.has_value());
  EXPECT_EQ(s.push->step, 2);
  EXPECT_FALSE(s.push->time.has_value()) << "a swept push acts at mid single support";
}

TEST(Scenario, StiffnessNeedsTheImpedanceGroundAndNamesAreChecked) {
  Scenario s;  // rigid ground
  EXPECT_THROW(setSweepValue(s, "stiffness", 1e6), std::invalid_argument);
  EXPECT_TRUE(std::isnan(sweepValue(s, "stiffness")));
  EXPECT_THROW(setSweepValue(s, "wind", 1), std::invalid_argument);
  EXPECT_THROW(sweepParameter("wind"), std::invalid_argument);
}

TEST(Scenario, APushNeedsAWalkThatReachesItsStep) {
  Scenario s;
  s.steps = Push{}.step - 1;
  EXPECT_THROW(setSweepValue(s, "push", 1.0), std::invalid_argument);
  EXPECT_FALSE(s.push.has_value());
  s.steps = Push{}.step;
  setSweepValue(s, "push", 1.0);
  EXPECT_EQ(sweepValue(s, "push"), 1.0);
}

TEST(Scenario, UncertaintyGoesToThePlantOrToTheControllersModel) {
  const auto& nominal = test::fiveLinkRobot();
  Scenario s;
  s.parameter_errors = dynamics::muUncertaintyCase(2);
  s.friction = 0.3;
  EXPECT_NEAR(scenarioPlant(nominal, s).totalMass(), 1.4 * nominal.totalMass(), 1e-12);
  EXPECT_EQ(scenarioPlant(nominal, s).friction(), 0.3);
  EXPECT_EQ(scenarioControllerModel(nominal, s).totalMass(), nominal.totalMass());
  s.errors_on_controller = true;  // Mu's setting
  EXPECT_EQ(scenarioPlant(nominal, s).totalMass(), nominal.totalMass());
  EXPECT_EQ(scenarioPlant(nominal, s).friction(), 0.3);
  EXPECT_NEAR(scenarioControllerModel(nominal, s).totalMass(), 1.4 * nominal.totalMass(), 1e-12);
}

// Mu's sliding-mode law sizes its switching term by the model error it is told of: in Mu's
// setting the error its model has, whether a case's, a --mass-error's or a sweep point's (the
// bound once stayed the case's, 0 in case 1, and a 30 % mass error walked with no switching).
TEST(Scenario, MusLawIsToldTheErrorItsModelHas) {
  Scenario s;
  EXPECT_EQ(uncertaintyBound(s).mass, kPlantErrorBound.mass);  // errors on the plant
  EXPECT_EQ(uncertaintyBound(s).length, kPlantErrorBound.length);
  s.errors_on_controller = true;
  s.parameter_errors = dynamics::muUncertaintyCase(1);
  setSweepValue(s, "mass_error", 0.3);
  EXPECT_EQ(uncertaintyBound(s).mass, 0.3);
  EXPECT_EQ(uncertaintyBound(s).inertia, 0.3);
  EXPECT_EQ(uncertaintyBound(s).length, 0.0);
  // A model 20 % short of the plant's lengths: the plant's are 1 / 0.8 = 1.25 times its own,
  // inside the box of b = 0.25, and the law's corners need b >= 0.
  setSweepValue(s, "length_error", -0.2);
  EXPECT_NEAR(uncertaintyBound(s).length, 0.25, 1e-15);
  EXPECT_NEAR(uncertaintyBound(s).com, 0.25, 1e-15);
}

}  // namespace
}  // namespace gaitopt::sim
