// The registries of controllers and grounds (sim/controllers/controller_registry.hpp,
// sim/walk/ground_registry.hpp): an unknown name is refused with every registered name listed
// (by the lookups, the scenario and the ground setting of sim/scenario/scenario_settings.hpp);
// every registered ground ships its configs/grounds/NAME.yaml, which loads as that ground; and
// every controller for an actuated ankle, built by its name, gives the reference's torques on
// the reference.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <set>
#include <string>
#include <vector>

#include "config/config_error.hpp"
#include "io/data_dir.hpp"
#include "sim/contact/ground_config.hpp"
#include "sim/scenario/scenario.hpp"
#include "sim/scenario/scenario_settings.hpp"
#include "sim/walk/ground_registry.hpp"
#include "tests/sim/five_link_gait.hpp"

namespace gaitopt::sim {
namespace {

/// The message of the std::invalid_argument `f` throws.
template <class F>
std::string refusal(const F& f) {
  try {
    f();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  ADD_FAILURE() << "nothing refused";
  return "";
}

void expectNamesEvery(const std::string& message, const std::vector<std::string>& names) {
  for (const std::string& name : names)
    EXPECT_NE(message.find(name), std::string::npos) << name << " is not in: " << message;
}

TEST(Registry, AnUnknownControllerIsRefusedNamingEveryRegisteredOne) {
  const std::string lookup = refusal([] { controllerEntry("pid"); });
  EXPECT_NE(lookup.find("unknown controller 'pid'"), std::string::npos) << lookup;
  expectNamesEvery(lookup, controllerNames());
  Scenario s;
  s.controller = "pid";
  s.steps = 1;
  const Reference ref(test::polynomialGait());
  EXPECT_EQ(refusal([&] { runScenario(test::fiveLinkRobot(), ref, s); }), lookup);
}

TEST(Registry, AnUnknownGroundIsRefusedNamingEveryRegisteredOne) {
  const std::string lookup = refusal([] { groundEntry("ice"); });
  EXPECT_NE(lookup.find("unknown ground 'ice'"), std::string::npos) << lookup;
  expectNamesEvery(lookup, groundNames());
}

TEST(Registry, AGroundSettingThatIsNeitherANameNorAFileIsRefusedNamingEveryGround) {
  EXPECT_EQ(groundPath("rigid"), io::dataFile("configs/grounds/rigid.yaml"));
  try {
    groundPath("ice");
    ADD_FAILURE() << "ice accepted";
  } catch (const config::ConfigError& e) {
    EXPECT_EQ(e.file(), "ice");
    expectNamesEvery(e.what(), groundNames());
  }
}

TEST(Registry, NamesAreUniqueEachHasAOneLineDescriptionAndTheDefaultsAreRegistered) {
  EXPECT_EQ(controllerEntry(kDefaultController).name, Scenario{}.controller);
  EXPECT_EQ(groundEntry(kDefaultGround).name, ScenarioSettings{}.ground);
  for (const auto& names : {controllerNames(), groundNames()})
    EXPECT_EQ(std::set<std::string>(names.begin(), names.end()).size(), names.size());
  for (const ControllerEntry& c : controllers()) {
    EXPECT_FALSE(c.description.empty()) << c.name;
    EXPECT_EQ(c.description.find('\n'), std::string::npos) << c.name;
  }
  for (const GroundEntry& g : grounds()) {
    EXPECT_FALSE(g.description.empty()) << g.name;
    EXPECT_EQ(g.description.find('\n'), std::string::npos) << g.name;
  }
}

TEST(Registry, EveryRegisteredGroundShipsAFileThatLoadsAsThatGround) {
  const std::string dir = std::string(GAITOPT_SOURCE_DIR) + "/configs/grounds/";
  std::set<std::string> shipped;
  for (const auto& file : std::filesystem::directory_iterator(dir))
    if (file.path().extension() == ".yaml") shipped.insert(file.path().stem().string());
  const std::vector<std::string> names = groundNames();
  EXPECT_EQ(shipped, std::set<std::string>(names.begin(), names.end()));
  for (const GroundEntry& g : grounds()) {
    const GroundModel model = loadGround(dir + g.name + ".yaml");
    EXPECT_EQ(groundName(model), g.name);
    EXPECT_TRUE(model.type() == g.settings) << g.name;
  }
}

// On the reference (the state is the reference knot's, no memory yet) a tracking law adds
// nothing: the torques are the reference's inverse dynamics on the exact model (Mu 2.43), and
// Mu's law is its equivalent control (4.4) with s = 0, so its switching term tanh(0) vanishes.
// The reference torques lie within the robot's limits, so the clipping changes nothing.
TEST(Registry, EveryControllerBuiltByNameGivesTheReferencesTorquesOnTheReference) {
  const dynamics::Model& robot = test::fiveLinkRobot();
  const Reference ref(test::polynomialGait(), robot);
  Scenario s;
  int tracking = 0;
  for (const ControllerEntry& c : controllers()) {
    if (c.passive_ankle) continue;  // HZD tracks its own outputs (hzd_test.cpp)
    ++tracking;
    s.controller = c.name;
    const auto controller = makeController(robot, ref, s);
    double worst = 0;
    for (const gaits::Knot& k : test::polynomialGait().knots()) {
      if (k.phase != gaits::Phase::kSsp) continue;
      const Eigen::VectorXd memory =
          controller->phaseStartMemory(k.phase, k.theta, k.dtheta, k, nullptr);
      const VecD tau = controller->torque(k.phase, k.theta, k.dtheta, k, memory);
      worst = std::max(worst, (tau - VecD(k.tau)).cwiseAbs().maxCoeff());
    }
    RecordProperty(c.name + "_torque_off_reference", fmt::format("{:.2e}", worst));
    EXPECT_LT(worst, 1e-8) << c.name;
  }
  EXPECT_GE(tracking, 3);  // computed torque, sliding mode, Mu's sliding mode
}

}  // namespace
}  // namespace gaitopt::sim
