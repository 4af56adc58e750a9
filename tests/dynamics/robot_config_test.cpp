// Robot files: every shipped file loads; every bad file names the file, the key and what was
// expected, and never crashes.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>

#include "config/config_error.hpp"
#include "support/fixtures.hpp"

namespace gaitopt::test {
namespace {

/// The five-link file with one textual substitution, written to a temporary file.
class BadRobotFile : public ::testing::Test {
 protected:
  std::string write(const std::string& from, const std::string& to) {
    std::ifstream in(robotPath("mu2004_five_link"));
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const auto pos = text.find(from);
    EXPECT_NE(pos, std::string::npos) << "fixture text not found: " << from;
    text.replace(pos, from.size(), to);
    std::ofstream(path_) << text;
    return path_;
  }

  /// Loads and returns the error message; fails the test when loading succeeds.
  std::string errorOf(const std::string& path) {
    try {
      dynamics::loadRobot(path);
    } catch (const config::ConfigError& e) {
      EXPECT_EQ(e.file(), path);
      return e.what();
    }
    ADD_FAILURE() << "loading succeeded";
    return {};
  }

  void TearDown() override { std::filesystem::remove(path_); }
  std::string path_ = (std::filesystem::temp_directory_path() /
                       ("gaitopt_bad_robot_" + std::to_string(::getpid()) + ".yaml"))
                          .string();
};

TEST(RobotConfig, EveryShippedRobotLoads) {
  for (const auto& name : allRobots()) {
    const auto model = loadNamed(name);
    EXPECT_EQ(model.name(), name);
    EXPECT_GT(model.totalMass(), 0);
  }
}

TEST_F(BadRobotFile, MissingKey) {
  const std::string msg = errorOf(write("gravity: 9.81\n", ""));
  EXPECT_NE(msg.find("key 'gravity': missing required key"), std::string::npos) << msg;
}

TEST_F(BadRobotFile, NegativeMassNamesLinkAndExpectation) {
  const std::string msg = errorOf(write("mass: 5.28", "mass: -5.28"));
  EXPECT_NE(msg.find("key 'links[1].mass'"), std::string::npos) << msg;
  EXPECT_NE(msg.find("expected a number in [0.001, 10000] [kg], got -5.28"), std::string::npos)
      << msg;
  EXPECT_TRUE(std::regex_search(msg, std::regex(R"(\.yaml:\d+: )"))) << "line number: " << msg;
}

TEST_F(BadRobotFile, ZeroLength) {
  const std::string msg = errorOf(write("length: 0.486", "length: 0"));
  EXPECT_NE(msg.find("key 'links[2].length': expected a number in [0.001, 100] [m], got 0"),
            std::string::npos)
      << msg;
}

// mass 1e308 overflowed the mass matrix to NaN with exit 0: refused, range named.
TEST_F(BadRobotFile, AbsurdMassNamesThePlausibleRange) {
  const std::string msg = errorOf(write("mass: 5.28", "mass: 1e308"));
  EXPECT_NE(msg.find("key 'links[1].mass': expected a number in [0.001, 10000] [kg], got 1e308"),
            std::string::npos)
      << msg;
}

TEST_F(BadRobotFile, UnknownKey) {
  const std::string msg = errorOf(write("friction: 0.6", "friction: 0.6\nfrction: 0.5"));
  EXPECT_NE(msg.find("key 'frction': unknown key; allowed here: name, description, gravity"),
            std::string::npos)
      << msg;
}

TEST_F(BadRobotFile, NonNumericValue) {
  const std::string msg = errorOf(write("inertia: 0.033, length: 0.302, com: 0.236",
                                        "inertia: heavy, length: 0.302, com: 0.236"));
  EXPECT_NE(msg.find("key 'links[1].inertia': expected a finite number, got 'heavy'"),
            std::string::npos)
      << msg;
}

TEST_F(BadRobotFile, NotANumberIsRejected) {
  const std::string msg = errorOf(write("gravity: 9.81", "gravity: .nan"));
  EXPECT_NE(msg.find("key 'gravity': expected a finite number"), std::string::npos) << msg;
}

TEST_F(BadRobotFile, DegreesWhereRadiansAreExpected) {
  // 10 rad/s written as 573 deg/s is caught by range.
  const std::string msg = errorOf(write("velocity_limit: 10}", "velocity_limit: 573}"));
  EXPECT_NE(msg.find("velocity_limit': expected a number in [1e-06, 100] [rad/s], got 573"),
            std::string::npos)
      << msg;
}

TEST_F(BadRobotFile, ComBeyondTheLink) {
  const std::string msg = errorOf(write("com: 0.282", "com: 0.9"));
  EXPECT_NE(msg.find("links[2].com': expected a number in [0, 0.486] [m] (within the link"),
            std::string::npos)
      << msg;
}

TEST_F(BadRobotFile, LegsThatDoNotMirror) {
  const std::string msg = errorOf(write("mass: 2.23, inertia: 0.033, length: 0.332, com: 0.143",
                                        "mass: 2.5, inertia: 0.033, length: 0.332, com: 0.143"));
  EXPECT_NE(msg.find("link 'swing_shank' must mirror 'stance_shank'"), std::string::npos) << msg;
}

TEST_F(BadRobotFile, MalformedYamlReportsLine) {
  const std::string msg = errorOf(write("links:", "links: [unclosed"));
  EXPECT_NE(msg.find("not valid YAML"), std::string::npos) << msg;
}

// Found by fuzz/robot_yaml_fuzz: a key that is not a plain scalar escaped the reader as
// YAML::TypedBadConversion instead of a ConfigError.
TEST_F(BadRobotFile, MappingAsKey) {
  const std::string msg =
      errorOf(write("{name: stance_knee,", "{{velocit: true}: 10, name: stance_knee,"));
  EXPECT_NE(msg.find("key 'joints[1]': expected a plain key, got a mapping as a key"),
            std::string::npos)
      << msg;
}

TEST_F(BadRobotFile, NullKey) {
  const std::string msg = errorOf(write("friction: 0.6\n", "friction: 0.6\n~: 1\n"));
  EXPECT_TRUE(std::regex_search(
      msg, std::regex(R"(\.yaml:\d+: expected a plain key, got an empty value \(null\) as a key)")))
      << msg;
}

TEST_F(BadRobotFile, MissingFile) {
  const std::string msg = errorOf("/nonexistent/robot.yaml");
  EXPECT_NE(msg.find("/nonexistent/robot.yaml: file not found"), std::string::npos) << msg;
}

}  // namespace
}  // namespace gaitopt::test
