// The gait designed with model variants driven by the closed loop's law
// (configs/ocp/mu2004_walk_ensemble.yaml) walked on plants that are not its model: 20 steps on
// the rigid ground under computed torque on the nominal model, with the plant's links 5 % lighter
// and 20 % heavier, the foot's centre of pressure held inside the shipped foot (a rotation is a
// fall). The default optimum (mu2004_walk.yaml), walked the same way, falls on both plants.
#include <gtest/gtest.h>

#include <memory>
#include <string>

#include <fmt/format.h>

#include "dynamics/model_variation.hpp"
#include "dynamics/robot_files/robot_config.hpp"
#include "ocp/guess/initial_guess.hpp"
#include "ocp/solve/gait_solve.hpp"
#include "sim/contact/ground_config.hpp"
#include "sim/controllers/tracking_controller.hpp"
#include "sim/controllers/tracking_law.hpp"
#include "sim/walk/walk.hpp"

namespace gaitopt::sim {
namespace {

/// The 1 kHz export of a shipped config's optimum as a reference on the nominal robot.
struct Solved {
  explicit Solved(const std::string& name)
      : config(
            ocp::loadOcpConfig(std::string(GAITOPT_SOURCE_DIR) + "/configs/ocp/" + name + ".yaml")),
        nominal(dynamics::loadRobot(config.robot_path)),
        solution(ocp::solveGait(nominal, config, ocp::polynomialGuess(nominal, config))),
        reference(ocp::reconstructDense(solution.problem, nominal, solution.result.x, 1000.0),
                  nominal) {}
  ocp::OcpConfig config;
  dynamics::Model nominal;
  ocp::GaitSolution solution;
  Reference reference;
};

WalkResult walkOn(const Solved& s, double mass_error) {
  const dynamics::Model plant = dynamics::perturbedModel(s.nominal, {mass_error, mass_error, 0, 0});
  const TrackingController controller(s.nominal, std::make_shared<PdLaw>(400, 40));
  ContactRules rules;
  rules.cop_limit = CopLimit::kFail;
  return walk(plant, controller, s.reference,
              loadGround(std::string(GAITOPT_SOURCE_DIR) + "/configs/grounds/rigid.yaml"),
              {20, {}, rules});
}

class EnsembleWalk : public ::testing::TestWithParam<double> {
 protected:
  static void SetUpTestSuite() {
#ifdef NDEBUG
    ensemble_ = new Solved("mu2004_walk_ensemble");
    default_ = new Solved("mu2004_walk");
#endif
  }
  static void TearDownTestSuite() {
    delete ensemble_;
    delete default_;
  }
  void SetUp() override {
    if (!ensemble_) GTEST_SKIP() << "two OCP solves and walks of 20 steps: optimised builds only";
  }
  static Solved* ensemble_;
  static Solved* default_;
};
Solved* EnsembleWalk::ensemble_ = nullptr;
Solved* EnsembleWalk::default_ = nullptr;

TEST_P(EnsembleWalk, TheEnsembleOptimumWalksAPlantTheDefaultOptimumFallsOn) {
  ASSERT_TRUE(ensemble_->solution.result.success) << ensemble_->solution.result.status;
  ASSERT_TRUE(default_->solution.result.success);
  const double mass_error = GetParam();
  const WalkResult designed = walkOn(*ensemble_, mass_error);
  const WalkResult plain = walkOn(*default_, mass_error);
  RecordProperty("default_optimum",
                 fmt::format("{} steps: {}", plain.steps_completed, plain.failure));
  EXPECT_EQ(designed.steps_completed, 20) << designed.failure;
  EXPECT_LT(plain.steps_completed, 20) << "the default optimum walked this plant too";
  // At near-optimal cost: within twice the default optimum's.
  EXPECT_LT(ensemble_->solution.result.cost, 2 * default_->solution.result.cost);
}

INSTANTIATE_TEST_SUITE_P(PlantMass, EnsembleWalk, ::testing::Values(-0.05, 0.2),
                         [](const auto& info) {
                           return info.param < 0 ? std::string("lighter5") : "heavier20";
                         });

}  // namespace
}  // namespace gaitopt::sim
