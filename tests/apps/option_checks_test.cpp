// A quantity is checked in one place (config/quantities.hpp): the scenario's command-line option
// and the stability sweep of the same parameter accept and refuse the same values, in the same
// words. --controller takes the registered names (sim/controllers/controller_registry.hpp).
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <CLI/CLI.hpp>

#include "apps/option_checks.hpp"
#include "apps/study_commands/scenario_options.hpp"
#include "config/config_error.hpp"
#include "sim/studies/sweep_study.hpp"

namespace gaitopt::apps {
namespace {

/// The refusal of `option value` on a command line of the scenario options, or nullopt.
std::optional<std::string> optionRefusal(const std::string& option, const std::string& value) {
  CLI::App app;
  sim::ScenarioSettings settings;
  addScenarioOptions(&app, settings);
  requireFiniteNumbers(app);
  try {
    app.parse(std::vector<std::string>{value, option, "ref", "--reference"});  // reversed argv
  } catch (const CLI::ValidationError& e) {
    return e.what();
  }
  return std::nullopt;
}

/// The refusal of a sweep of `parameter` at `value`, or nullopt.
std::optional<std::string> sweepRefusal(const sim::SweepParameter& parameter, double value) {
  try {
    sim::sweepValues(parameter, {value, value, 1});
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return std::nullopt;
}

/// Both ends, just beyond them, the overflowing and the non-finite.
std::vector<double> probes(const config::Quantity& q) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  return {q.lo,
          q.hi,
          std::nextafter(q.lo, -kInf),
          std::nextafter(q.hi, kInf),
          0.5 * (q.lo + q.hi),
          1e308,
          -1e308,
          kInf,
          std::nan("")};
}

TEST(OptionChecks, TheOptionAndTheSweepRefuseTheSameValues) {
  int compared = 0;
  for (const sim::SweepParameter& p : sim::sweepParameters()) {
    if (p.name() == "stiffness") continue;  // a ground file's key, no option
    std::string option = "--" + p.name();
    std::replace(option.begin(), option.end(), '_', '-');
    for (const double v : probes(p.quantity)) {
      const auto by_option = optionRefusal(option, fmt::format("{}", v));
      const auto by_sweep = sweepRefusal(p, v);
      EXPECT_EQ(by_option.has_value(), by_sweep.has_value()) << option << " " << v;
      // The same words for a finite value; NaN and Inf in those of every number option.
      if (by_option && by_sweep && std::isfinite(v)) {
        EXPECT_EQ(*by_option, option + ": " + *by_sweep);
      }
      ++compared;
    }
  }
  EXPECT_EQ(compared, 5 * 9);
}

TEST(OptionChecks, TheControllerOptionTakesEveryRegisteredNameAndRefusesOthersNamingThem) {
  for (const std::string& name : sim::controllerNames())
    EXPECT_FALSE(optionRefusal("--controller", name)) << name;
  const auto refusal = optionRefusal("--controller", "pid");
  ASSERT_TRUE(refusal);
  EXPECT_NE(refusal->find("pid"), std::string::npos) << *refusal;
  for (const std::string& name : sim::controllerNames())
    EXPECT_NE(refusal->find(name), std::string::npos) << name << " is not in: " << *refusal;
}

TEST(OptionChecks, AGridBeyondTheMemoryBudgetIsRefusedNamingItsSource) {
  EXPECT_NO_THROW(requireGridFits(1e6, 512, "--map a,b"));
  try {
    requireGridFits(1e12, 512, "--map a,b");
    FAIL() << "a grid of 1e12 points accepted";
  } catch (const config::ConfigError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("--map a,b: a grid of 1e+12 points needs about", 0), 0u)
        << e.what();
  }
}

}  // namespace
}  // namespace gaitopt::apps
