// A gait folder exported on the fixed-rate grid (gaits/export/gait_export.hpp) as the simulator's
// reference: loadReferenceFolder puts the switch states of summary.json back, so the SSP part
// ends at the touchdown with the pre-impact state, the DSP part starts there with the
// post-impact state and ends at the period, and away from the switch the reference is the one
// the step itself gives.
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "config/config_error.hpp"
#include "five_link_gait.hpp"
#include "gaits/export/gait_export.hpp"
#include "gaits/export/gait_summary.hpp"
#include "sim/controllers/reference.hpp"
#include "sim/scenario/reference_folder.hpp"

namespace gaitopt::sim {
namespace {

using gaits::Phase;

constexpr double kRate = 128;  // Hz: the touchdown (0.6 s) and the end (0.7 s) are off the grid

/// theta1..thetaN (or another prefix) of a row object of summary.json.
VecD rowValues(const nlohmann::json& row, const char* prefix, int n) {
  VecD v(n);
  for (int j = 0; j < n; ++j) v(j) = row[fmt::format("{}{}", prefix, j + 1)].get<double>();
  return v;
}

class ReferenceFolderTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto& model = test::fiveLinkRobot();
    const auto params =
        gaits::loadGait(std::string(GAITOPT_SOURCE_DIR) + "/configs/gaits/mu2004.yaml");
    step_ = gaits::buildTrajectory(
        gaits::PolynomialGait(model, params, gaits::searchHipPlan(model, params).plan), model,
        kRate);
    dir_ = std::filesystem::temp_directory_path() /
           fmt::format("gaitopt_reference_folder_{}", ::getpid());
    std::filesystem::create_directories(dir_);
    gaits::writeGaitExport(dir_.string(), step_, model, kRate,
                           gaits::gaitSummary(step_, model, {"", "designed"}));
    std::ifstream in(dir_ / "summary.json");
    summary_ = nlohmann::json::parse(in);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  ReferenceFolder load() const {
    return loadReferenceFolder(
        dir_.string(), std::string(GAITOPT_SOURCE_DIR) + "/configs/robots/mu2004_five_link.yaml");
  }

  gaits::Trajectory step_;
  std::filesystem::path dir_;
  nlohmann::json summary_;
};

TEST_F(ReferenceFolderTest, EachPartSpansItsPhaseWithTheSwitchStatesOfTheSummary) {
  const ReferenceFolder folder = load();
  const Reference ref(folder.step, folder.model);
  const auto& s = summary_["phase_switches"].at(0);
  const double t_switch = s["t"].get<double>();
  EXPECT_EQ(ref.touchdownTime(), t_switch);
  EXPECT_EQ(ref.endTime(), summary_["duration"].get<double>());
  // The SSP part's last knot is the pre-switch state, the DSP part's first the post-switch one.
  const gaits::Knot pre = ref.at(Phase::kSsp, t_switch);
  EXPECT_EQ(VecD(pre.theta), rowValues(s["before"], "theta", 5));
  EXPECT_EQ(VecD(pre.dtheta), rowValues(s["before"], "dtheta", 5));
  EXPECT_EQ(VecD(pre.ddtheta), rowValues(s["before"], "ddtheta", 5));
  const gaits::Knot post = ref.at(Phase::kDsp, t_switch);
  EXPECT_EQ(VecD(post.theta), rowValues(s["after"], "theta", 5));
  EXPECT_EQ(VecD(post.dtheta), rowValues(s["after"], "dtheta", 5));
  EXPECT_EQ(post.force_swing.y(), s["after"]["fe_y"].get<double>());
  // The DSP part ends at the period (off the grid) in the state of step_end.
  const gaits::Knot end = ref.at(Phase::kDsp, ref.endTime());
  EXPECT_EQ(VecD(end.theta), rowValues(summary_["step_end"], "theta", 5));
  EXPECT_EQ(VecD(end.dtheta), rowValues(summary_["step_end"], "dtheta", 5));
}

TEST_F(ReferenceFolderTest, AwayFromTheSwitchTheReferenceIsTheStepsOwn) {
  const ReferenceFolder folder = load();
  const Reference read(folder.step, folder.model);
  const Reference direct(step_, folder.model);
  int compared = 0;
  for (double t = 0; t <= 0.7; t += 0.0037) {
    if (std::abs(t - 0.6) < 1 / kRate) continue;
    const Phase phase = t < 0.6 ? Phase::kSsp : Phase::kDsp;
    const gaits::Knot a = read.at(phase, t), b = direct.at(phase, t);
    EXPECT_LT((a.theta - b.theta).cwiseAbs().maxCoeff(), 1e-12) << t;
    EXPECT_LT((a.dtheta - b.dtheta).cwiseAbs().maxCoeff(), 1e-12) << t;
    EXPECT_LT((a.ddtheta - b.ddtheta).cwiseAbs().maxCoeff(), 1e-12) << t;
    EXPECT_LT((a.tau - b.tau).cwiseAbs().maxCoeff(), 1e-12) << t;
    ++compared;
  }
  EXPECT_GT(compared, 180);
}

// A robot file of the gait's name but other masses is another robot: walked by default, the gait
// fell on the shipped robot it does not fit. A --set robot.KEY=V changes the robot walked on
// purpose and stays allowed.
TEST_F(ReferenceFolderTest, AGaitOfAnotherRobotOfTheSameNameIsRefused) {
  const std::string robot =
      std::string(GAITOPT_SOURCE_DIR) + "/configs/robots/mu2004_five_link.yaml";
  std::ifstream in(robot);
  std::stringstream text;
  text << in.rdbuf();
  const std::string heavy = (dir_ / "heavy.yaml").string();
  std::string edited = text.str();
  const auto at = edited.find("mass: 14.79");  // the torso
  ASSERT_NE(at, std::string::npos);
  edited.replace(at, 11, "mass: 26.79");
  std::ofstream(heavy) << edited;
  try {
    loadReferenceFolder(dir_.string(), heavy);
    FAIL() << "a gait of a 29.81 kg robot walked on a 41.81 kg one";
  } catch (const config::ConfigError& e) {
    EXPECT_NE(std::string(e.what()).find("designed for a robot 'mu2004_five_link' of 29.81 kg"),
              std::string::npos)
        << e.what();
  }
  EXPECT_NO_THROW(loadReferenceFolder(dir_.string(), robot, {{"links[2].mass", "26.79"}}));
}

}  // namespace
}  // namespace gaitopt::sim
