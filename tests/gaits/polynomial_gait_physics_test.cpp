// Physics of Mu's gait (Table 3.1, S_L = 0.70 m, T_S = 0.6 s, T_D = 0.1 s, apex (0, 0.05 m))
// with the hip plan chosen by NLopt: ground forces, friction, ZMP, DSP load sharing, and an
// independent re-simulation of the exported torques.
#include <gtest/gtest.h>

#include <filesystem>

#include <fmt/format.h>

#include "dynamics/dsp_dynamics.hpp"
#include "dynamics/ground.hpp"
#include "dynamics/model_variation.hpp"
#include "dynamics/robot_files/robot_config.hpp"
#include "dynamics/ssp_dynamics.hpp"
#include "gaits/export/gait_export.hpp"
#include "gaits/export/metrics.hpp"
#include "gaits/polynomial/dsp_force_distribution.hpp"
#include "gaits/polynomial/hip_plan_search.hpp"
#include "gaits/trajectory/trajectory_csv.hpp"
#include "support/chain_simulation.hpp"
#include "support/fixtures.hpp"

namespace gaitopt::test {
namespace {

using gaits::Phase;

class MuGaitPhysics : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    model_ = new dynamics::Model(loadNamed("mu2004_five_link"));
    params_ = new gaits::GaitParams(
        gaits::loadGait(std::string(GAITOPT_SOURCE_DIR) + "/configs/gaits/mu2004.yaml"));
    search_ = new gaits::HipPlanSearch(gaits::searchHipPlan(*model_, *params_));
    const gaits::PolynomialGait gait(*model_, *params_, search_->plan);
    traj_ = new gaits::Trajectory(gaits::buildTrajectory(gait, *model_, 1000));
  }
  static void TearDownTestSuite() {
    delete traj_;
    delete search_;
    delete params_;
    delete model_;
  }
  static dynamics::Model* model_;
  static gaits::GaitParams* params_;
  static gaits::HipPlanSearch* search_;
  static gaits::Trajectory* traj_;
};
dynamics::Model* MuGaitPhysics::model_ = nullptr;
gaits::GaitParams* MuGaitPhysics::params_ = nullptr;
gaits::HipPlanSearch* MuGaitPhysics::search_ = nullptr;
gaits::Trajectory* MuGaitPhysics::traj_ = nullptr;

TEST_F(MuGaitPhysics, HipPlanSearchFindsAWideDspMargin) {
  RecordProperty("V_h1", fmt::format("{:.4f}", search_->plan.velocity_start));
  RecordProperty("V_h2", fmt::format("{:.4f}", search_->plan.velocity_touchdown));
  RecordProperty("S_D0", fmt::format("{:.4f}", search_->plan.dsp_start));
  RecordProperty("dsp_margin", fmt::format("{:.4f}", search_->margin));
  RecordProperty("evaluations", search_->evaluations);
  // Mu: the ZMP stays near the centre of the DSP support; the best margin is half the support.
  EXPECT_GT(search_->margin, 0.35 * params_->step_length);
  EXPECT_LE(search_->margin, 0.5 * params_->step_length + 1e-9);
  // The optimum is at least as good as the hand-picked plan of
  // docs/derivations.md#the-polynomial-gait.
  const gaits::PolynomialGait by_hand(*model_, *params_,
                                      {0.3, 0.3, 0.17, params_->hip_start, params_->hip_height});
  EXPECT_GE(search_->margin, gaits::dspStabilityMargin(by_hand, *model_, 41) - 1e-9);
}

TEST_F(MuGaitPhysics, VerticalGroundForcesStayPositive) {
  const double min_fn = gaits::minNormalForce(*traj_);
  RecordProperty("min_normal_force_N", fmt::format("{:.2f}", min_fn));
  EXPECT_GT(min_fn, 0.0);
}

TEST_F(MuGaitPhysics, FrictionCoefficientOfPointFourSuffices) {
  const double ratio = gaits::maxFrictionRatio(*traj_);
  RecordProperty("max_friction_ratio", fmt::format("{:.4f}", ratio));
  EXPECT_LE(ratio, 0.4);
  // With mu = 0.4 in the robot, every DSP load share stays feasible.
  const auto model04 = dynamics::withFriction(*model_, 0.4);
  for (const auto& k : traj_->knots()) {
    if (k.phase != Phase::kDsp) continue;
    EXPECT_TRUE(gaits::distributeDspForces(model04, k.theta, k.dtheta, k.ddtheta).feasible)
        << "t = " << k.t;
  }
}

TEST_F(MuGaitPhysics, DspZmpStaysWellInsideTheSupportAndEqualsTheCentreOfPressure) {
  double margin = 1e9;
  for (const auto& k : traj_->knots()) {
    if (k.phase != Phase::kDsp) continue;
    const double cop = gaits::zmpX(k, traj_->stepLength());
    const double zmp = dynamics::zeroMomentPoint<double>(*model_, k.theta, k.dtheta, k.ddtheta);
    EXPECT_NEAR(cop, zmp, 1e-7);
    margin = std::min({margin, zmp, traj_->stepLength() - zmp});
    // Forces and torques satisfy the constrained dynamics (2.11).
    const VecR<double> r =
        dynamics::dspResidual<double>(*model_, k.theta, k.dtheta, k.ddtheta, k.tau, k.force_swing);
    EXPECT_LT(r.norm(), 1e-8);
  }
  RecordProperty("dsp_zmp_margin_1kHz", fmt::format("{:.4f}", margin));
  EXPECT_GT(margin, 0.35 * traj_->stepLength());
}

TEST_F(MuGaitPhysics, ExportedTorquesReproduceTheSspByForwardSimulation) {
  // Export (1 kHz grid, switch states in summary.json), re-import, then integrate
  // D ddtheta + N = M^T tau(t) from the exported initial state with tau linear between the
  // samples (as a controller would apply them).
  const auto dir =
      std::filesystem::temp_directory_path() / fmt::format("gaitopt_resim_{}", ::getpid());
  std::filesystem::create_directories(dir);
  gaits::writeGaitExport(dir.string(), *traj_, *model_, 1000, nlohmann::ordered_json::object());
  const gaits::Trajectory imported =
      gaits::readTrajectoryCsv((dir / "trajectory.csv").string(), *model_);
  std::filesystem::remove_all(dir);

  const double t_s = params_->ssp_duration - 1e-12;  // the SSP side of the touchdown
  double max_err = 0;
  const auto& k0 = imported.knots().front();
  test::simulateSsp(
      *model_, k0.theta, k0.dtheta,
      [&](double t) { return VecD(imported.at(std::min(t, t_s)).tau); },
      test::evenTimes(params_->ssp_duration, 600), 1e-10,
      [&](double t, const VecD& theta, const VecD&) {
        const VecD ref = imported.at(std::min(t, t_s)).theta;
        max_err = std::max(max_err, (theta - ref).cwiseAbs().maxCoeff());
      });
  RecordProperty("resimulation_max_angle_error_rad", fmt::format("{:.3e}", max_err));
  EXPECT_LT(max_err, 1e-3);
}

// A fair baseline for the shipped foot (configs/gaits/mu2004_zmp.yaml): the hip-plan search
// that also keeps the single support's ZMP inside the foot, with the hip's start and height free,
// finds a gait whose ZMP stays inside [-heel, toe] at every 1 kHz sample of the whole step, where
// Mu's plan puts it more than 10 cm behind the heel.
TEST_F(MuGaitPhysics, TheHipSearchForTheFootKeepsTheSingleSupportZmpInsideIt) {
  const gaits::GaitParams fair =
      gaits::loadGait(std::string(GAITOPT_SOURCE_DIR) + "/configs/gaits/mu2004_zmp.yaml");
  ASSERT_EQ(fair.hip_objective, gaits::HipObjective::kZmp);
  const gaits::HipPlanSearch search = gaits::searchHipPlan(*model_, fair);
  EXPECT_GT(search.ssp_margin, 0.02);
  EXPECT_GT(search.dsp_margin, 0.02);
  EXPECT_NE(search.plan.height, fair.hip_height);  // searched, not the file's 0.59 m
  const gaits::Trajectory dense =
      gaits::buildTrajectory(gaits::PolynomialGait(*model_, fair, search.plan), *model_, 1000);
  EXPECT_GT(gaits::minZmpMargin(dense, *model_), 0.02);
  EXPECT_LT(gaits::minZmpMargin(*traj_, *model_), -0.1);  // Mu's plan
  EXPECT_LT(search_->ssp_margin, -0.1);
}

}  // namespace
}  // namespace gaitopt::test
