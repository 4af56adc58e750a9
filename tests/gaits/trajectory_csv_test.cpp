// trajectory.csv (docs/design.md#the-export-contract): exact round trip, derived columns, and one
// error per kind of malformed file, each naming the file, the line and the column.
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "config/config_error.hpp"
#include "dynamics/joint_coordinates.hpp"
#include "dynamics/kinematics.hpp"
#include "gaits/export/metrics.hpp"
#include "gaits/trajectory/trajectory_csv.hpp"
#include "gaits/trajectory/trajectory_json.hpp"
#include "gaits/trajectory/trajectory_text.hpp"
#include "support/fixtures.hpp"
#include "support/same_knots.hpp"
#include "support/text_fields.hpp"

namespace gaitopt::test {
namespace {

using gaits::Knot;
using gaits::Phase;
using gaits::Trajectory;

std::string readText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream buf;
  buf << in.rdbuf();
  return buf.str();
}

void writeText(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

std::string join(const std::vector<std::string>& parts, char sep) {
  std::string out;
  for (size_t i = 0; i < parts.size(); ++i) out += (i ? std::string(1, sep) : "") + parts[i];
  return out;
}

/// A five-link step that is smooth but not physical, with awkward decimals (0.1 * k, 1/7) so
/// the 17-digit round trip is really exercised: SSP on [0, 0.6], DSP on [0.6, 0.7].
Trajectory syntheticStep(const dynamics::Model& model) {
  const Eigen::VectorXd posture =
      (Eigen::VectorXd(5) << 0.2, 0.15, 0.05, std::numbers::pi - 0.25, std::numbers::pi - 0.3)
          .finished();
  const Eigen::ArrayXd phase = Eigen::ArrayXd::LinSpaced(5, 0.0, 1.0);
  std::vector<Knot> knots;
  const auto add = [&](double t, Phase p) {
    Knot k;
    k.t = t;
    k.phase = p;
    k.theta = posture.array() + 0.1 * (3 * t + phase).sin();
    k.dtheta = 0.3 * (3 * t + phase).cos();
    k.ddtheta = -0.9 * (3 * t + phase).sin();
    k.tau = 20 * (t + phase).sin() + (p == Phase::kDsp ? 1.0 / 7 : 0.0);
    k.force_stance = Eigen::Vector2d(3.1 + t, 250 - 100 * t / 3);
    if (p == Phase::kDsp) k.force_swing = Eigen::Vector2d(-2.7, 90 + 1.0 / 7);
    knots.push_back(k);
  };
  for (int i = 0; i <= 6; ++i) add(0.1 * i, Phase::kSsp);
  add(0.1 * 6, Phase::kDsp);
  add(0.65, Phase::kDsp);
  add(0.7, Phase::kDsp);
  // The reader takes the step length from the last swing_x, so the writer's must agree.
  const double step_length = dynamics::swingTip(model, VecD(knots.back().theta))(0);
  return Trajectory(model.name(), step_length, knots);
}

class TrajectoryCsv : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = std::filesystem::temp_directory_path() /
           fmt::format("gaitopt_csv_{}_{}", info->name(), ::getpid());
    std::filesystem::create_directories(dir_);
    good_ = path("good.csv");
    gaits::writeTrajectoryCsv(traj_.knots(), traj_.stepLength(), model_, good_);
    lines_ = split(readText(good_), '\n');
    header_ = split(lines_.front(), ',');
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  /// The good file with one field replaced; `line` is 1-based like the error messages.
  std::string withField(int line, const std::string& column, const std::string& value) const {
    std::vector<std::string> lines = lines_;
    std::vector<std::string> fields = split(lines.at(static_cast<size_t>(line - 1)), ',');
    const auto it = std::find(header_.begin(), header_.end(), column);
    fields.at(static_cast<size_t>(it - header_.begin())) = value;
    lines[static_cast<size_t>(line - 1)] = join(fields, ',');
    return join(lines, '\n') + "\n";
  }

  double field(int line, const std::string& column) const {
    const auto fields = split(lines_.at(static_cast<size_t>(line - 1)), ',');
    const auto it = std::find(header_.begin(), header_.end(), column);
    return std::stod(fields.at(static_cast<size_t>(it - header_.begin())));
  }

  /// Writes `text` as bad.csv, reads it and returns the error; checks file, key and line.
  config::ConfigError errorOf(const std::string& text, const std::string& key, int line,
                              const dynamics::Model* model = nullptr) const {
    const std::string bad = path("bad.csv");
    writeText(bad, text);
    try {
      gaits::readTrajectoryCsv(bad, model ? *model : model_);
    } catch (const config::ConfigError& e) {
      EXPECT_EQ(e.file(), bad);
      EXPECT_EQ(e.key(), key);
      EXPECT_EQ(e.line(), line);
      return e;
    }
    ADD_FAILURE() << "reading succeeded";
    return config::ConfigError("", "", 0, "");
  }

  dynamics::Model model_ = loadNamed("mu2004_five_link");
  Trajectory traj_ = syntheticStep(model_);
  std::filesystem::path dir_;
  std::string good_;
  std::vector<std::string> lines_, header_;
};

/// Checks that `what` holds every fragment.
void expectMessage(const config::ConfigError& e, const std::vector<std::string>& fragments) {
  const std::string what = e.what();
  for (const auto& f : fragments) EXPECT_NE(what.find(f), std::string::npos) << what;
}

// --- round trip and content ------------------------------------------------------------------

TEST_F(TrajectoryCsv, RoundTripIsExactAndByteIdentical) {
  const Trajectory back = gaits::readTrajectoryCsv(good_, model_);
  expectSameKnots(traj_, back);
  EXPECT_EQ(back.stepLength(), traj_.stepLength());
  EXPECT_EQ(back.robot(), "mu2004_five_link");
  const std::string again = path("again.csv");
  gaits::writeTrajectoryCsv(back.knots(), back.stepLength(), model_, again);
  EXPECT_EQ(readText(again), readText(good_));
  EXPECT_FALSE(std::filesystem::exists(again + ".tmp")) << "temporary file left behind";
}

TEST_F(TrajectoryCsv, JsonVariantHoldsTheSameColumnsAndNumbers) {
  const std::string json_path = path("trajectory.json");
  gaits::writeTrajectoryJson(traj_.knots(), traj_.stepLength(), model_, json_path);
  const auto json = nlohmann::json::parse(readText(json_path));
  EXPECT_EQ(json["robot"], "mu2004_five_link");
  EXPECT_EQ(json["step_length"].get<double>(), traj_.stepLength());
  ASSERT_EQ(json["columns"].get<std::vector<std::string>>(), header_);
  for (size_t c = 0; c < header_.size(); ++c) {
    const auto& column = json["data"][header_[c]];
    ASSERT_EQ(column.size(), traj_.knots().size()) << header_[c];
    for (size_t k = 0; k < traj_.knots().size(); k += 7) {
      const std::string csv = split(lines_[k + 1], ',')[c];
      if (header_[c] == "phase")
        EXPECT_EQ(column[k].get<std::string>(), csv);
      else
        EXPECT_EQ(column[k].get<double>(), std::stod(csv)) << header_[c] << " row " << k;
    }
  }
}

// A failed solve's folder may hold non-finite numbers; JSON has none, so they become null and
// the file still parses (the CSV keeps "nan", which its reader rejects by name).
TEST_F(TrajectoryCsv, JsonVariantWritesNullWhereANumberIsNotFinite) {
  std::vector<Knot> knots = traj_.knots();
  knots[3].tau(1) = std::numeric_limits<double>::quiet_NaN();
  knots[4].tau(1) = std::numeric_limits<double>::infinity();
  knots[6].tau(2) = -std::numeric_limits<double>::infinity();
  const std::string json_path = path("not_finite.json");
  gaits::writeTrajectoryJson(knots, traj_.stepLength(), model_, json_path);
  const auto json = nlohmann::json::parse(readText(json_path));
  const auto& tau1 = json["data"]["tau1"];
  EXPECT_TRUE(tau1[3].is_null());
  EXPECT_TRUE(tau1[4].is_null());
  EXPECT_EQ(tau1[5].get<double>(), knots[5].tau(1));
  EXPECT_TRUE(json["data"]["tau2"][6].is_null());
  EXPECT_TRUE(json["data"]["t"][0].is_number_float());  // 0 is written 0.0, as nlohmann does
}

// The text both files are written from is formatted in two halves at once; any row count,
// odd or a single row, must give every row's every cell, each reading back exactly.
TEST_F(TrajectoryCsv, SharedTextHoldsEveryCellOfAnyRowCount) {
  for (const size_t count : {size_t{1}, size_t{2}, size_t{9}}) {
    const std::vector<Knot> knots(traj_.knots().begin(), traj_.knots().begin() + count);
    const gaits::TrajectoryText text(knots, traj_.stepLength(), model_);
    ASSERT_EQ(text.rows(), count);
    const std::vector<std::string> lines = split(text.csvLines(), '\n');
    ASSERT_EQ(lines.size(), count);
    for (size_t k = 0; k < count; ++k) {
      const std::vector<std::string> cells = split(lines[k], ',');
      ASSERT_EQ(cells.size(), header_.size()) << "row " << k << " of " << count;
      for (size_t c = 0; c < cells.size(); ++c) EXPECT_EQ(text.cell(k, c), cells[c]);
      EXPECT_EQ(cells, split(lines_[k + 1], ','));  // the same as the file of all rows
      EXPECT_EQ(std::stod(cells[0]), knots[k].t);
      EXPECT_EQ(std::stod(cells[2]), knots[k].theta(0));
    }
  }
  EXPECT_THROW(gaits::TrajectoryText({}, traj_.stepLength(), model_), std::invalid_argument);
}

TEST_F(TrajectoryCsv, HeaderFollowsDesignSection5) {
  EXPECT_EQ(
      lines_.front(),
      "t,phase,theta1,theta2,theta3,theta4,theta5,dtheta1,dtheta2,dtheta3,dtheta4,dtheta5,"
      "ddtheta1,ddtheta2,ddtheta3,ddtheta4,ddtheta5,q0,q1,q2,q3,q4,dq0,dq1,dq2,dq3,dq4,"
      "tau0,tau1,tau2,tau3,tau4,fb_x,fb_y,fe_x,fe_y,zmp_x,hip_x,hip_y,swing_x,swing_y,com_x,com_y,"
      "left_ankle,left_knee,left_hip,right_hip,right_knee,dleft_ankle,dleft_knee,dleft_hip,"
      "dright_hip,dright_knee,tau_left_ankle,tau_left_knee,tau_left_hip,tau_right_hip,"
      "tau_right_knee");
  EXPECT_EQ(lines_.size(), 1 + traj_.knots().size());
}

TEST_F(TrajectoryCsv, DerivedColumnsComeFromTheModel) {
  for (size_t k : {size_t{0}, size_t{7}, traj_.knots().size() - 1}) {
    const int line = static_cast<int>(k) + 2;
    const Knot& knot = traj_.knots()[k];
    const VecD theta = knot.theta;
    const VecD q = dynamics::toJoint(theta);
    const VecD dq = dynamics::toJoint(VecD(knot.dtheta));
    for (int j = 0; j < 5; ++j) {
      EXPECT_EQ(field(line, fmt::format("q{}", j)), q(j));
      EXPECT_EQ(field(line, fmt::format("dq{}", j)), dq(j));
    }
    const Vec2d hip = dynamics::hip(model_, theta);
    const Vec2d swing = dynamics::swingTip(model_, theta);
    EXPECT_EQ(field(line, "hip_x"), hip(0));
    EXPECT_EQ(field(line, "hip_y"), hip(1));
    EXPECT_EQ(field(line, "swing_x"), swing(0));
    EXPECT_EQ(field(line, "swing_y"), swing(1));
    const Vec2d com = dynamics::centreOfMass(model_, theta);
    EXPECT_EQ(field(line, "com_x"), com(0));
    EXPECT_EQ(field(line, "com_y"), com(1));
    EXPECT_EQ(field(line, "zmp_x"), gaits::zmpX(knot, traj_.stepLength()));
  }
  EXPECT_EQ(split(lines_[7], ',')[1], "SSP");  // knot 6 (line 8): last SSP knot
  EXPECT_EQ(split(lines_[8], ',')[1], "DSP");  // knot 7 (line 9): first DSP knot, same time
  EXPECT_EQ(split(lines_[7], ',')[0], split(lines_[8], ',')[0]);
}

TEST_F(TrajectoryCsv, WriterRejectsAnotherRobot) {
  const auto three = loadNamed("three_link");
  EXPECT_THROW(gaits::writeTrajectoryCsv(traj_.knots(), traj_.stepLength(), three, path("x.csv")),
               std::invalid_argument);
}

// --- malformed files -------------------------------------------------------------------------

TEST_F(TrajectoryCsv, MissingFile) {
  const std::string missing = path("nope.csv");
  try {
    gaits::readTrajectoryCsv(missing, model_);
    ADD_FAILURE() << "reading succeeded";
  } catch (const config::ConfigError& e) {
    expectMessage(e, {missing, "not found"});
  }
}

TEST_F(TrajectoryCsv, EmptyFile) {
  expectMessage(errorOf("", "", 0), {"bad.csv: empty file, expected the header t,phase,theta1"});
}

TEST_F(TrajectoryCsv, HeaderOnly) {
  expectMessage(errorOf(lines_.front() + "\n", "", 1), {"bad.csv:1: no data rows"});
}

TEST_F(TrajectoryCsv, TruncatedLastLine) {
  std::string text = readText(good_);
  text.resize(text.size() - 30);  // cut inside the last row, as a killed writer would
  const int last = static_cast<int>(lines_.size());
  expectMessage(
      errorOf(text, "", last),
      {fmt::format("bad.csv:{}: expected 58 comma-separated fields", last), "(truncated line?)"});
}

TEST_F(TrajectoryCsv, TextInsteadOfANumber) {
  expectMessage(errorOf(withField(4, "theta2", "abc"), "theta2", 4),
                {"bad.csv:4: key 'theta2': expected a number, found 'abc'"});
}

TEST_F(TrajectoryCsv, NanValue) {
  expectMessage(errorOf(withField(3, "tau1", "nan"), "tau1", 3),
                {"bad.csv:3: key 'tau1': non-finite value 'nan'"});
}

TEST_F(TrajectoryCsv, MissingHeaderColumn) {
  std::vector<std::string> header = header_;
  header.erase(header.begin() + 9);  // dtheta3
  std::vector<std::string> lines = lines_;
  lines[0] = join(header, ',');
  expectMessage(errorOf(join(lines, '\n'), "dtheta3", 1),
                {"bad.csv:1: key 'dtheta3': missing column (column 10 should be 'dtheta3')",
                 "expected t,phase,theta1..theta5,"});
}

TEST_F(TrajectoryCsv, MisnamedHeaderColumn) {
  std::vector<std::string> lines = lines_;
  lines[0] = join(header_, ',');
  lines[0].replace(lines[0].find("fb_y"), 4, "fb_z");
  expectMessage(errorOf(join(lines, '\n'), "fb_y", 1),
                {"bad.csv:1: key 'fb_y': column 34 is 'fb_z', expected 'fb_y'"});
}

TEST_F(TrajectoryCsv, UnknownPhase) {
  expectMessage(errorOf(withField(5, "phase", "XSP"), "phase", 5),
                {"bad.csv:5: key 'phase': unknown phase 'XSP', expected SSP or DSP"});
}

TEST_F(TrajectoryCsv, DecreasingTime) {
  expectMessage(errorOf(withField(6, "t", "0.05"), "t", 6),
                {"bad.csv:6: key 't': time 0.050000000000000003 is before the previous row's "
                 "0.30000000000000004"});
}

TEST_F(TrajectoryCsv, InconsistentJointAngle) {
  const double q2 = field(7, "q2");
  expectMessage(errorOf(withField(7, "q2", fmt::format("{:.17g}", q2 + 1e-6)), "q2", 7),
                {"bad.csv:7: key 'q2':", "disagrees with M theta (Mu 2.41)"});
  // Within the tolerance: accepted.
  writeText(path("close.csv"), withField(7, "q2", fmt::format("{:.17g}", q2 + 1e-12)));
  EXPECT_NO_THROW(gaits::readTrajectoryCsv(path("close.csv"), model_));
}

TEST_F(TrajectoryCsv, InconsistentJointRate) {
  expectMessage(errorOf(withField(2, "dq4", "12"), "dq4", 2),
                {"bad.csv:2: key 'dq4': 12 disagrees with M dtheta"});
}

TEST_F(TrajectoryCsv, LinkCountMustMatchTheRobot) {
  const auto three = loadNamed("three_link");
  expectMessage(errorOf(readText(good_), "", 1, &three),
                {"bad.csv:1: the file has columns for 5 links (theta1..theta5) but robot "
                 "'three_link' has 3 links"});
}

TEST_F(TrajectoryCsv, PhaseOrderIsChecked) {
  // First data row DSP, then SSP rows: a phase change without a switch pair.
  expectMessage(errorOf(withField(2, "phase", "DSP"), "", 0),
                {"bad.csv: rows do not form a trajectory: knots 0 and 1 change phase DSP -> SSP",
                 "knot k is on line k + 2"});
}

}  // namespace
}  // namespace gaitopt::test
