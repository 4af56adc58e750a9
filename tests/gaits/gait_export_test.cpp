// A gait folder's export (gaits/export/gait_export.hpp) of Mu's polynomial gait at 128 Hz, where
// neither the touchdown (0.6 s) nor the end (0.7 s) is on the grid: trajectory.csv on
// t_i = i / 128 with time strictly increasing, the switch states and the end in summary.json,
// and readTrajectoryCsv giving the step back knot for knot.
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "config/config_error.hpp"
#include "gaits/export/consistency.hpp"
#include "gaits/export/export_checks.hpp"
#include "gaits/export/gait_export.hpp"
#include "gaits/export/gait_summary.hpp"
#include "gaits/polynomial/hip_plan_search.hpp"
#include "gaits/polynomial/polynomial_gait.hpp"
#include "gaits/trajectory/trajectory_csv.hpp"
#include "support/fixtures.hpp"
#include "support/text_fields.hpp"

namespace gaitopt::test {
namespace {

using gaits::Knot;
using gaits::Phase;
using gaits::Trajectory;

constexpr double kRate = 128;  // Hz: 0.6 * 128 = 76.8 and 0.7 * 128 = 89.6, both off the grid

nlohmann::json readJson(const std::filesystem::path& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

void writeJson(const std::filesystem::path& path, const nlohmann::json& json) {
  std::ofstream(path) << json.dump(2);
}

class GaitExport : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    model_ = new dynamics::Model(loadNamed("mu2004_five_link"));
    const auto params =
        gaits::loadGait(std::string(GAITOPT_SOURCE_DIR) + "/configs/gaits/mu2004.yaml");
    const gaits::PolynomialGait gait(*model_, params, gaits::searchHipPlan(*model_, params).plan);
    step_ = new Trajectory(gaits::buildTrajectory(gait, *model_, kRate));
  }
  static void TearDownTestSuite() {
    delete step_;
    delete model_;
  }

  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = std::filesystem::temp_directory_path() /
           fmt::format("gaitopt_export_{}_{}", info->name(), ::getpid());
    std::filesystem::create_directories(dir_);
    samples_ = gaits::writeGaitExport(dir_.string(), *step_, *model_, kRate,
                                      gaits::gaitSummary(*step_, *model_, {"", "designed"}));
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  std::string csv() const { return (dir_ / "trajectory.csv").string(); }
  /// The error of reading the folder's trajectory.csv.
  config::ConfigError readError() const {
    try {
      gaits::readTrajectoryCsv(csv(), *model_);
    } catch (const config::ConfigError& e) {
      return e;
    }
    ADD_FAILURE() << "reading succeeded";
    return config::ConfigError("", "", 0, "");
  }

  static dynamics::Model* model_;
  static Trajectory* step_;
  std::filesystem::path dir_;
  size_t samples_ = 0;
};
dynamics::Model* GaitExport::model_ = nullptr;
Trajectory* GaitExport::step_ = nullptr;

TEST_F(GaitExport, CsvAndJsonTimesAreIOverRateStrictlyIncreasing) {
  std::ifstream in(csv());
  std::stringstream text;
  text << in.rdbuf();
  const std::vector<std::string> lines = split(text.str(), '\n');
  ASSERT_EQ(samples_, 90u);  // i = 0..89: 89 / 128 = 0.6953 <= 0.7 < 90 / 128
  ASSERT_EQ(lines.size(), 1 + samples_);
  const auto json = readJson(dir_ / "trajectory.json");
  ASSERT_EQ(json["data"]["t"].size(), samples_);
  double previous = -1;
  for (size_t i = 0; i < samples_; ++i) {
    const std::vector<std::string> fields = split(lines[i + 1], ',');
    const double t = std::stod(fields[0]);
    EXPECT_NEAR(t, static_cast<double>(i) / kRate, 1e-12) << "row " << i;
    EXPECT_GT(t, previous) << "row " << i;
    EXPECT_EQ(fields[1], t < 0.6 ? "SSP" : "DSP") << "row " << i;
    EXPECT_EQ(json["data"]["t"][i].get<double>(), t) << "row " << i;
    previous = t;
  }
}

TEST_F(GaitExport, SummaryKeepsTheStatesEitherSideOfTheSwitchAndAtTheEnd) {
  const auto summary = readJson(dir_ / "summary.json");
  EXPECT_EQ(summary["sample_rate_hz"].get<double>(), kRate);
  EXPECT_EQ(summary["duration"].get<double>(), step_->endTime());  // the period, off the grid
  ASSERT_EQ(summary["phase_switches"].size(), 1u);
  const auto& s = summary["phase_switches"][0];
  const auto pair = std::find_if(step_->knots().begin(), step_->knots().end(),
                                 [](const Knot& k) { return k.phase == Phase::kDsp; });
  const Knot &before = *(pair - 1), &after = *pair;
  EXPECT_EQ(s["t"].get<double>(), 0.6);
  EXPECT_EQ(s["from"], "SSP");
  EXPECT_EQ(s["to"], "DSP");
  EXPECT_EQ(s["before"]["phase"], "SSP");
  EXPECT_EQ(s["after"]["phase"], "DSP");
  for (int j = 0; j < 5; ++j) {
    EXPECT_EQ(s["before"][fmt::format("theta{}", j + 1)].get<double>(), before.theta(j));
    EXPECT_EQ(s["before"][fmt::format("dtheta{}", j + 1)].get<double>(), before.dtheta(j));
    EXPECT_EQ(s["after"][fmt::format("ddtheta{}", j + 1)].get<double>(), after.ddtheta(j));
    EXPECT_EQ(s["after"][fmt::format("tau{}", j)].get<double>(), after.tau(j));
    EXPECT_EQ(summary["step_end"][fmt::format("theta{}", j + 1)].get<double>(),
              step_->knots().back().theta(j));
  }
  EXPECT_EQ(summary["step_end"]["t"].get<double>(), step_->endTime());
  EXPECT_EQ(summary["step_end"]["fe_y"].get<double>(), step_->knots().back().force_swing.y());
}

// The foot of configs/robots/mu2004_five_link.yaml, which the pictures draw the ZMP against.
TEST_F(GaitExport, SummaryNamesTheFootOfTheRobot) {
  const auto summary = readJson(dir_ / "summary.json");
  EXPECT_EQ(summary["foot"]["heel"].get<double>(), 0.05);
  EXPECT_EQ(summary["foot"]["toe"].get<double>(), 0.15);
}

TEST_F(GaitExport, ReadingTheFolderGivesTheStepBackAndTheSameChecks) {
  const Trajectory back = gaits::readTrajectoryCsv(csv(), *model_);
  ASSERT_EQ(back.knots().size(), step_->knots().size());
  for (size_t k = 0; k < back.knots().size(); ++k) {
    const Knot &x = back.knots()[k], &y = step_->knots()[k];
    EXPECT_EQ(x.t, y.t) << k;
    EXPECT_EQ(x.phase, y.phase) << k;
    EXPECT_EQ(x.theta, y.theta) << k;
    EXPECT_EQ(x.dtheta, y.dtheta) << k;
    EXPECT_EQ(x.ddtheta, y.ddtheta) << k;
    EXPECT_EQ(x.tau, y.tau) << k;
    EXPECT_EQ(x.force_stance, y.force_stance) << k;
    EXPECT_EQ(x.force_swing, y.force_swing) << k;
  }
  EXPECT_NEAR(back.stepLength(), step_->stepLength(), 1e-12);
  // The checks on the dense export see the same knots, so the same numbers: the rate mismatch
  // does not difference across the switch, whose rates jump.
  EXPECT_EQ(gaits::maxRateMismatch(back), gaits::maxRateMismatch(*step_));
  EXPECT_LT(gaits::maxRateMismatch(back), 1e-2);  // 4.0e-3: O(h^2) differences at 128 Hz
  EXPECT_EQ(gaits::maxDynamicsResidual(back, *model_), gaits::maxDynamicsResidual(*step_, *model_));
  EXPECT_EQ(gaits::periodicityError(back, *model_), gaits::periodicityError(*step_, *model_));
}

TEST_F(GaitExport, AGridFileWithoutItsSwitchStatesIsAnError) {
  std::filesystem::remove(dir_ / "summary.json");
  const config::ConfigError e = readError();
  EXPECT_EQ(e.file(), csv());
  EXPECT_NE(std::string(e.what()).find("phase_switches of the summary.json"), std::string::npos)
      << e.what();
}

TEST_F(GaitExport, ACutOrRetimedGridFileIsAnError) {
  // Read as it is, a file cut short would jump from its last row to the stored end state.
  std::ifstream in(csv());
  std::stringstream text;
  text << in.rdbuf();
  in.close();
  std::vector<std::string> lines = split(text.str(), '\n');
  const auto write = [&](const std::vector<std::string>& rows) {
    std::ofstream out(csv());
    for (const auto& row : rows) out << row << '\n';
  };
  write({lines.begin(), lines.end() - 1});
  config::ConfigError e = readError();
  EXPECT_NE(std::string(e.what()).find("89 row(s) on the grid, but t_i = i / 128 Hz up to the "
                                       "step's end at 0.7 s (summary.json) makes 90"),
            std::string::npos)
      << e.what();
  // Row 4 (line 6) moved 1e-11 s off 4 / 128 = 0.03125.
  lines[5] = "0.03125000001" + lines[5].substr(lines[5].find(','));
  write(lines);
  e = readError();
  EXPECT_EQ(e.key(), "t");
  EXPECT_EQ(e.line(), 6);
}

TEST_F(GaitExport, AMalformedSwitchRecordNamesItsKey) {
  auto summary = readJson(dir_ / "summary.json");
  summary["phase_switches"][0]["before"]["q2"] =
      summary["phase_switches"][0]["before"]["q2"].get<double>() + 1e-6;
  writeJson(dir_ / "summary.json", summary);
  EXPECT_EQ(readError().key(), "phase_switches[0].before.q2");
  summary = readJson(dir_ / "summary.json");
  summary["phase_switches"][0]["before"]["q2"] = summary["phase_switches"][0]["after"]["q2"];
  summary["phase_switches"][0]["after"]["phase"] = "SSP";
  writeJson(dir_ / "summary.json", summary);
  EXPECT_EQ(readError().key(), "phase_switches[0]");
  summary.erase("step_end");
  writeJson(dir_ / "summary.json", summary);
  EXPECT_EQ(readError().key(), "step_end");
}

}  // namespace
}  // namespace gaitopt::test
