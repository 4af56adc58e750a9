// loadLibraryConfig: axes given as a range, a list or a scalar, an axis left out (the base
// problem's value), and the errors a hand-written file can hold, each naming the key.
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include <unistd.h>

#include <gtest/gtest.h>

#include "config/config_error.hpp"
#include "library/library_config.hpp"

namespace gaitopt::library {
namespace {

const std::string kOcp = std::string(GAITOPT_SOURCE_DIR) + "/configs/ocp/mu2004_walk.yaml";

/// A library YAML on the shipped five-link problem with `grid` (and `extra` top-level lines).
std::string writeLibrary(const std::string& name, const std::string& grid,
                         const std::string& extra = "") {
  const std::string path =
      ::testing::TempDir() + "gaitopt_library_" + std::to_string(::getpid()) + "_" + name + ".yaml";
  std::ofstream(path) << "name: " << name << "\nocp: " << kOcp << "\n"
                      << extra << "grid:\n"
                      << grid;
  return path;
}

/// The ConfigError message of loading the file, or "no error".
std::string errorOf(const std::string& path) {
  try {
    loadLibraryConfig(path);
  } catch (const config::ConfigError& e) {
    return e.what();
  }
  return "no error";
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(LibraryConfig, RangeListScalarAndMissingAxis) {
  const std::string path = writeLibrary(
      "good", "  speed: {from: 0.3, to: 0.9, count: 4}\n  step_length: [0.4, 0.3, 0.35]\n");
  const LibraryConfig c = loadLibraryConfig(path);
  EXPECT_EQ(c.name, "good");
  EXPECT_EQ(c.path, path);
  EXPECT_TRUE(std::filesystem::equivalent(c.ocp_path, kOcp));
  ASSERT_EQ(c.axes[kSpeed].size(), 4u);
  const std::vector<double> speeds = {0.3, 0.5, 0.7, 0.9};
  for (std::size_t k = 0; k < 4; ++k) EXPECT_NEAR(c.axes[kSpeed][k], speeds[k], 1e-12);
  // Lists are sorted.
  EXPECT_EQ(c.axes[kStepLength], (std::vector<double>{0.3, 0.35, 0.4}));
  // Slope left out: the base problem's.
  EXPECT_EQ(c.axes[kSlope], (std::vector<double>{c.base.slope}));
  EXPECT_EQ(c.base.slope, 0.0);

  const std::string scalar = writeLibrary("scalar", "  slope: -0.05\n  step_length: 0.3\n");
  const LibraryConfig s = loadLibraryConfig(scalar);
  EXPECT_EQ(s.axes[kSlope], (std::vector<double>{-0.05}));
  EXPECT_EQ(s.axes[kStepLength], (std::vector<double>{0.3}));
  // Speed left out: the base problem's own speed, step length / step duration.
  const std::array<double, 3> base = basePoint(s.base);
  ASSERT_EQ(s.axes[kSpeed].size(), 1u);
  EXPECT_DOUBLE_EQ(s.axes[kSpeed][0], base[kSpeed]);
  double duration = 0;
  for (const auto& phase : s.base.phases) duration += phase.duration;
  EXPECT_DOUBLE_EQ(base[kSpeed], s.base.step_length / duration);
  EXPECT_DOUBLE_EQ(base[kStepLength], s.base.step_length);

  // A range of one value is that value.
  const LibraryConfig one =
      loadLibraryConfig(writeLibrary("one", "  speed: {from: 0.5, to: 0.5, count: 1}\n"));
  EXPECT_EQ(one.axes[kSpeed], (std::vector<double>{0.5}));
}

TEST(LibraryConfig, ErrorsNameTheKey) {
  struct Case {
    const char* name;
    std::string grid, extra;
    std::vector<std::string> expected;  ///< parts of the message
  };
  const std::vector<Case> cases = {
      {"count_fraction",
       "  speed: {from: 0.3, to: 0.9, count: 2.5}\n",
       "",
       {"key 'grid.speed.count'", "a whole number in [1, 1000]", "2.5"}},
      {"count_zero",
       "  speed: {from: 0.3, to: 0.9, count: 0}\n",
       "",
       {"key 'grid.speed.count'", "a whole number"}},
      {"to_below_from",
       "  speed: {from: 0.9, to: 0.3, count: 3}\n",
       "",
       {"key 'grid.speed.to'", "expected a number > from (0.9)"}},
      {"to_equals_from",
       "  step_length: {from: 0.3, to: 0.3, count: 2}\n",
       "",
       {"key 'grid.step_length.to'", "> from (0.3)"}},
      {"duplicate",
       "  speed: [0.4, 0.6, 0.4]\n",
       "",
       {"key 'grid.speed'", "expected distinct values"}},
      {"degrees",
       "  slope: [0, 10]\n",
       "",
       {"key 'grid.slope[1]'", "[-0.35, 0.35] [rad]", "degrees? 10 deg is 0.1745 rad"}},
      {"negative_speed", "  speed: -0.5\n", "", {"key 'grid.speed'", "[m/s]", "-0.5"}},
      {"unknown_axis", "  speeds: [0.4]\n", "", {"key 'grid.speeds'", "unknown key"}},
      {"unknown_range_key",
       "  speed: {from: 0.3, to: 0.9, n: 3}\n",
       "",
       {"key 'grid.speed.n'", "unknown key"}},
      {"unknown_top", "  speed: 0.5\n", "solver: fast\n", {"key 'solver'", "unknown key"}},
      {"missing_count", "  speed: {from: 0.3, to: 0.9}\n", "", {"grid.speed.count"}},
      {"not_a_number", "  speed: [0.4, fast]\n", "", {"key 'grid.speed[1]'", "fast"}},
  };
  for (const Case& c : cases) {
    const std::string path = writeLibrary(c.name, c.grid, c.extra);
    const std::string message = errorOf(path);
    EXPECT_TRUE(contains(message, path + ":")) << c.name << ": " << message;
    for (const std::string& part : c.expected)
      EXPECT_TRUE(contains(message, part))
          << c.name << ": '" << message << "' lacks '" << part << "'";
  }
}

// Any numeric key of the base problem is an axis, dotted or nested as --set spells it; it starts
// from the base file's value; each value is checked as the OCP file would check it.
TEST(LibraryConfig, AnyNumericConfigKeyIsAnAxis) {
  const LibraryConfig c = loadLibraryConfig(
      writeLibrary("keys",
                   "  speed: 0.5\n  constraints.friction_margin: [0.3, 0.1]\n"
                   "  constraints:\n    zmp_margin: {from: 0.0, to: 0.02, count: 3}\n"));
  ASSERT_EQ(c.config_axes.size(), 2u);
  EXPECT_EQ(c.config_axes[0].key, "constraints.friction_margin");
  EXPECT_EQ(c.config_axes[0].values, (std::vector<double>{0.1, 0.3}));
  EXPECT_EQ(c.config_axes[1].key, "constraints.zmp_margin");
  EXPECT_EQ(c.config_axes[1].values.size(), 3u);
  // The shipped problem states friction_margin 0.15; zmp_margin is left to its default.
  ASSERT_EQ(c.config_base.size(), 2u);
  EXPECT_DOUBLE_EQ(c.config_base[0], c.base.friction_margin);
  EXPECT_DOUBLE_EQ(c.config_base[1], 0.01);  // the axis' middle
  // A point's base problem carries its values.
  const Grid grid(c.axes, c.config_axes);
  const ocp::OcpConfig at = baseAt(c, grid.point(grid.size() - 1));
  EXPECT_DOUBLE_EQ(at.friction_margin, 0.3);
  EXPECT_DOUBLE_EQ(at.zmp_margin, 0.02);
  EXPECT_EQ(basePoint(c).size(), 5u);
}

TEST(LibraryConfig, AConfigAxisIsCheckedAsTheOcpFileIs) {
  struct Case {
    const char* name;
    std::string grid;
    std::vector<std::string> expected;
  };
  const std::vector<Case> cases = {
      {"out_of_range",
       "  constraints.friction_margin: [0.1, 1.5]\n",
       {"key 'grid.constraints.friction_margin'", "constraints.friction_margin", "1.5"}},
      {"not_a_key",
       "  constraints.frictoin_margin: [0.1]\n",
       {"grid.constraints.frictoin_margin", "unknown key"}},
      {"a_word_key", "  scheme: [1, 2]\n", {"key 'grid.scheme'"}},
      {"set_by_the_walk", "  phases[0].duration: [0.5, 0.6]\n", {"grid.speed"}},
      {"not_numbers", "  constraints.friction_margin: [0.1, high]\n", {"high"}},
  };
  for (const Case& c : cases) {
    const std::string message = errorOf(writeLibrary(c.name, c.grid));
    for (const std::string& part : c.expected)
      EXPECT_TRUE(contains(message, part))
          << c.name << ": '" << message << "' lacks '" << part << "'";
  }
}

TEST(LibraryConfig, MissingOcpFileIsAConfigError) {
  const std::string path = ::testing::TempDir() + "gaitopt_library_noocp.yaml";
  std::ofstream(path) << "name: x\nocp: no_such_problem.yaml\ngrid: {speed: 0.5}\n";
  const std::string message = errorOf(path);
  EXPECT_TRUE(contains(message, "no_such_problem.yaml")) << message;
  EXPECT_TRUE(
      contains(errorOf(::testing::TempDir() + "gaitopt_no_such_library.yaml"), "file not found"));
}

}  // namespace
}  // namespace gaitopt::library
