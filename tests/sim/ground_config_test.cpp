// Ground files: every shipped file loads into the model it names with its values; an unknown
// key, ground or out-of-range value is a ConfigError naming the file and the key (an unknown
// ground also every registered one).
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "config/config_error.hpp"
#include "sim/contact/ground_config.hpp"
#include "sim/walk/ground_registry.hpp"

namespace gaitopt::sim {
namespace {

std::string shippedGround(const std::string& name) {
  return std::string(GAITOPT_SOURCE_DIR) + "/configs/grounds/" + name + ".yaml";
}

TEST(GroundConfig, EveryShippedFileLoadsAsTheModelItNames) {
  const auto rigid = loadGround(shippedGround("rigid"));
  ASSERT_NE(rigid.getIf<RigidGround>(), nullptr);
  EXPECT_GT(rigid.getIf<RigidGround>()->integrator.step, 0);
  EXPECT_EQ(groundName(rigid), "rigid");

  const auto impedance = loadGround(shippedGround("impedance"));
  ASSERT_NE(impedance.getIf<CompliantGround>(), nullptr);
  const auto& compliant = *impedance.getIf<CompliantGround>();
  EXPECT_EQ(compliant.contact.exponent, 1.5);
  EXPECT_EQ(compliant.contact.stiffness, 1e7);
  EXPECT_GT(compliant.time_step, 0);
  EXPECT_EQ(groundName(impedance), "impedance");

  const auto lcp = loadGround(shippedGround("lcp"));
  ASSERT_NE(lcp.getIf<LcpGround>(), nullptr);
  EXPECT_GT(lcp.getIf<LcpGround>()->time_step, 0);
  EXPECT_EQ(groundName(lcp), "lcp");
}

/// The impedance file with one textual substitution, written to a temporary file.
class BadGroundFile : public ::testing::Test {
 protected:
  void write(const std::string& from, const std::string& to) {
    std::ifstream in(shippedGround("impedance"));
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const auto pos = text.find(from);
    ASSERT_NE(pos, std::string::npos) << "fixture text not found: " << from;
    text.replace(pos, from.size(), to);
    std::ofstream(path_) << text;
  }

  /// The error of loading the written file; fails the test when loading succeeds.
  config::ConfigError errorOf() {
    try {
      loadGround(path_);
    } catch (const config::ConfigError& e) {
      EXPECT_EQ(e.file(), path_);
      return e;
    }
    ADD_FAILURE() << "loading succeeded";
    return {path_, "", 0, ""};
  }

  void TearDown() override { std::filesystem::remove(path_); }
  std::string path_ = (std::filesystem::temp_directory_path() /
                       ("gaitopt_bad_ground_" + std::to_string(::getpid()) + ".yaml"))
                          .string();
};

TEST_F(BadGroundFile, UnknownKeyIsNamed) {
  write("stiffness: 1.0e+7", "stiffness: 1.0e+7\nstifness: 2.0e+7");
  const auto e = errorOf();
  EXPECT_EQ(e.key(), "stifness") << e.what();
  EXPECT_GT(e.line(), 0);
}

TEST_F(BadGroundFile, NegativeStiffnessIsNamedWithTheExpectation) {
  write("stiffness: 1.0e+7", "stiffness: -1.0e+7");
  const auto e = errorOf();
  EXPECT_EQ(e.key(), "stiffness") << e.what();
  // The range of a stiffness sweep (config/quantities.hpp).
  EXPECT_NE(std::string(e.what()).find("expected a number in [100, 1e+12] [N/m^n], got -1.0e+7"),
            std::string::npos)
      << e.what();
}

TEST_F(BadGroundFile, UnknownModelIsNamedWithEveryRegisteredGround) {
  write("model: impedance", "model: trampoline");
  const auto e = errorOf();
  EXPECT_EQ(e.key(), "model");
  for (const std::string& name : groundNames())
    EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << name << ": " << e.what();
}

}  // namespace
}  // namespace gaitopt::sim
