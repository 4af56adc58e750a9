// The gait designed with model variants driven by the closed loop's law
// (configs/ocp/mu2004_walk_ensemble.yaml) walked on plants that are not its model, under computed
// torque on the nominal model: 20 steps on the rigid ground with the plant's links 20 % and 10 %
// lighter, 10 % and 20 % heavier or 5 % shorter, on the LCP ground (time stepping with Coulomb
// contact) 10 % lighter, and, in builds with DART, in DART with feet that are bodies, at the
// nominal mass and 10 % lighter and heavier. On the rigid and LCP grounds a centre of pressure
// beyond the shipped foot is a fall; in DART the foot tips by DART's own physics and the controller
// clips its ankle torque to the foot. The default optimum (mu2004_walk.yaml), walked the same way,
// falls on every one of these plants. And the design itself between its collocation points: every
// model of the ensemble meets its contact conditions on its own 1 kHz export, and the nominal's
// export stays upright.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <memory>
#include <numbers>
#include <optional>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include <fmt/format.h>

#include "dynamics/model_variation.hpp"
#include "dynamics/robot_files/robot_config.hpp"
#include "gaits/export/export_checks.hpp"
#include "gaits/export/metrics.hpp"
#include "ocp/guess/initial_guess.hpp"
#include "ocp/solve/gait_solve.hpp"
#include "sim/contact/ground_config.hpp"
#include "sim/controllers/tracking_controller.hpp"
#include "sim/controllers/tracking_law.hpp"
#include "sim/scenario/scenario.hpp"
#include "sim/scenario/scenario_settings.hpp"
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
        dense(ocp::reconstructDense(solution.problem, nominal, solution.result.x, 1000.0)),
        reference(dense, nominal) {}
  ocp::OcpConfig config;
  dynamics::Model nominal;
  ocp::GaitSolution solution;
  gaits::Trajectory dense;  ///< the nominal's 1 kHz export
  Reference reference;
};

/// A plant the gaits were not designed on: a ground (configs/grounds/NAME.yaml), a mass error
/// (every link's mass and inertia) and a length error (every length and centre of mass).
struct Plant {
  const char* ground;
  double mass_error;
  double length_error = 0;
};

void PrintTo(const Plant& p, std::ostream* os) {
  *os << p.ground << " ground, plant mass x" << 1 + p.mass_error << ", lengths x"
      << 1 + p.length_error;
}

/// A CoP beyond the foot is a fall on the toolkit's grounds, unless `cop` says otherwise; DART's
/// feet tip by its own physics, so there the controller clips its ankle torque to the foot.
WalkResult walkOn(const Solved& s, const Plant& p, const TrackingController& controller,
                  std::optional<CopLimit> cop = std::nullopt) {
  const dynamics::Model plant = dynamics::perturbedModel(
      s.nominal, {p.mass_error, p.mass_error, p.length_error, p.length_error});
  ContactRules rules;
  const bool dart = std::string(p.ground) == "dart";
  rules.cop_limit = cop.value_or(dart ? CopLimit::kSaturate : CopLimit::kFail);
  return walk(plant, controller, s.reference,
              loadGround(fmt::format("{}/configs/grounds/{}.yaml", GAITOPT_SOURCE_DIR, p.ground)),
              {20, {}, rules});
}

/// Under computed torque on the nominal model, the closed loop's gains (kp 400, kd 40).
WalkResult walkOn(const Solved& s, const Plant& p) {
  return walkOn(s, p, TrackingController(s.nominal, std::make_shared<PdLaw>(400, 40)));
}

/// A walk of `settings` under `controller` as `gaitopt simulate` builds it (makeScenario: Mu's
/// cases with Table 4.2's gains and the bound the controller is told), the CoP rule `cop`.
WalkResult walkAsSimulate(const Solved& s, ScenarioSettings settings, const char* controller,
                          CopLimit cop) {
  settings.controller = controller;
  settings.rules.cop_limit = cop;
  return runScenario(s.nominal, s.reference, makeScenario(settings)).walk;
}

/// The two optima, each solved once per process on first use.
const Solved& ensembleOptimum() {
  static const Solved s("mu2004_walk_ensemble");
  return s;
}
const Solved& defaultOptimum() {
  static const Solved s("mu2004_walk");
  return s;
}

/// Skips in builds without optimisation: the tests solve both optima and walk 20 steps.
class OptimisedOnly : public ::testing::Test {
 protected:
  void SetUp() override {
#ifndef NDEBUG
    GTEST_SKIP() << "two OCP solves and walks of 20 steps: optimised builds only";
#endif
  }
};

class EnsembleWalk : public ::testing::WithParamInterface<Plant>, public OptimisedOnly {};
class EnsembleExport : public OptimisedOnly {};

TEST_P(EnsembleWalk, TheEnsembleOptimumWalksAPlantTheDefaultOptimumFallsOn) {
  const Solved& ensemble = ensembleOptimum();
  const Solved& plain_optimum = defaultOptimum();
  ASSERT_TRUE(ensemble.solution.result.success) << ensemble.solution.result.status;
  ASSERT_TRUE(plain_optimum.solution.result.success);
  const WalkResult designed = walkOn(ensemble, GetParam());
  const WalkResult plain = walkOn(plain_optimum, GetParam());
  RecordProperty("default_optimum",
                 fmt::format("{} steps: {}", plain.steps_completed, plain.failure));
  EXPECT_EQ(designed.steps_completed, 20) << designed.failure;
  EXPECT_LT(plain.steps_completed, 20) << "the default optimum walked this plant too";
  // Issue 33's price of robustness: at most 2 times the default optimum's cost.
  EXPECT_LT(ensemble.solution.result.cost, 2 * plain_optimum.solution.result.cost);
}

/// Mu's cases 2 and 3 on the controller's side (its model +40 % masses and inertias, +10 %
/// lengths; +100 % and +40 %; the plant nominal), rigid ground, the ankle torque clipped to the
/// foot as results/mu_cases/ walks them: computed torque falls in step 1 on the ensemble optimum,
/// as it lifts the leading tip in the double support, where it computes the whole torque on its
/// model; with the plan's torques fed forward there (DspFeedForward::kPlan) it walks 20 steps
/// under both (with the double support collocated in theta, as shipped until 2026-11-29, it fell
/// in step 1 under case 3).
TEST_F(EnsembleExport, ThePlansDoubleSupportFeedForwardWalksMusCasesTwoAndThree) {
  const Solved& s = ensembleOptimum();
  ASSERT_TRUE(s.solution.result.success) << s.solution.result.status;
  for (const int mu_case : {2, 3}) {
    const dynamics::Model wrong =
        dynamics::perturbedModel(s.nominal, dynamics::muUncertaintyCase(mu_case));
    const auto walkWith = [&](DspFeedForward dsp) {
      return walkOn(s, {"rigid", 0.0},
                    TrackingController(wrong, std::make_shared<PdLaw>(400, 40), dsp),
                    CopLimit::kSaturate);
    };
    const WalkResult model = walkWith(DspFeedForward::kModel);
    const WalkResult plan = walkWith(DspFeedForward::kPlan);
    RecordProperty(fmt::format("case{}_model_feed_forward", mu_case),
                   fmt::format("{} steps: {}", model.steps_completed, model.failure));
    EXPECT_LT(model.steps_completed, 20) << "case " << mu_case;
    EXPECT_EQ(plan.steps_completed, 20) << "case " << mu_case << ": " << plan.failure;
  }
}

/// Mu's law on the ensemble optimum as `gaitopt simulate --controller mu_sliding_mode[_plan_dsp]`
/// walks it, a CoP beyond the shipped foot a fall: Mu's cases 2 and 3 on the controller's side
/// with Table 4.2's gains and the bound the controller is told (Mu's premise), rigid ground; and
/// the nominal on the LCP ground. With its equivalent control computed on its model in double
/// support it slides the trailing tip in step 2 under both cases (T^ presses the tips apart up to
/// the friction cone) and lifts the leading tip in step 1 on the LCP ground; with the plan's
/// double-support torques fed forward (mu_sliding_mode.hpp) it walks all three 20 of 20.
TEST_F(EnsembleExport, MusLawWithThePlansDoubleSupportWalksMusCasesAndTheLcpGround) {
  const Solved& s = ensembleOptimum();
  ASSERT_TRUE(s.solution.result.success) << s.solution.result.status;
  std::vector<std::pair<std::string, ScenarioSettings>> scenarios;
  for (const int mu_case : {2, 3}) {
    ScenarioSettings c;
    c.uncertainty_case = mu_case;
    c.uncertainty_on = "controller";
    scenarios.emplace_back(fmt::format("case {}", mu_case), c);
  }
  ScenarioSettings lcp;
  lcp.ground = "lcp";
  scenarios.emplace_back("LCP ground", lcp);
  for (const auto& [name, settings] : scenarios) {
    const WalkResult model = walkAsSimulate(s, settings, "mu_sliding_mode", CopLimit::kFail);
    const WalkResult plan =
        walkAsSimulate(s, settings, "mu_sliding_mode_plan_dsp", CopLimit::kFail);
    RecordProperty(name + " model_feed_forward",
                   fmt::format("{} steps: {}", model.steps_completed, model.failure));
    EXPECT_LT(model.steps_completed, 20) << name;
    EXPECT_EQ(plan.steps_completed, 20) << name << ": " << plan.failure;
  }
}

/// The plan-fed law's one loss on issue 33's plants is the CoP rule's, not the robot's: on the
/// rigid ground with every link 20 % heavier its commanded ankle torque puts the centre of
/// pressure beyond the foot in step 2 (a fall under the strict rule, recorded), and with the
/// ankle torque clipped to the foot, as results/mu_cases and results/ensemble_walks_clipped walk
/// it, it walks 20 of 20.
TEST_F(EnsembleExport, MusLawWithThePlansDoubleSupportWalksAHeavierPlantWithItsAnkleClipped) {
  const Solved& s = ensembleOptimum();
  ASSERT_TRUE(s.solution.result.success) << s.solution.result.status;
  ScenarioSettings heavier;
  heavier.mass_error = 0.2;
  const char* law = "mu_sliding_mode_plan_dsp";
  const WalkResult strict = walkAsSimulate(s, heavier, law, CopLimit::kFail);
  const WalkResult clipped = walkAsSimulate(s, heavier, law, CopLimit::kSaturate);
  RecordProperty("strict", fmt::format("{} steps: {}", strict.steps_completed, strict.failure));
  EXPECT_LT(strict.steps_completed, 20);
  EXPECT_NE(strict.failure.find("foot rotation"), std::string::npos) << strict.failure;
  EXPECT_EQ(clipped.steps_completed, 20) << clipped.failure;
}

/// Issue 33's check of the design itself, between the collocation points: every model of the
/// ensemble, exported at 1 kHz from the scheme's own polynomials, pushes on the ground with each
/// tip in contact inside its friction cone, keeps its stance foot's centre of pressure on the
/// foot, its swing tip above the ground and its double-support tip where it landed (within
/// issue 34's 1e-6 m: the double support is collocated in Mu's reduced coordinates, 2.13, each
/// copy's tip pinned at its own step, the nominal's times its length_scale; exported at the
/// nominal's, the copy 5 % shorter's tip sat 1.8 cm off). Collocated in the angles on 6
/// segments, the 10 % lighter copy's trailing foot had its centre of pressure 6 mm beyond the
/// foot for 3 ms after the touchdown.
TEST_F(EnsembleExport, EveryModelOfTheEnsembleMeetsItsContactConditionsOnTheOneKilohertzExport) {
  const Solved& s = ensembleOptimum();
  ASSERT_TRUE(s.solution.result.success) << s.solution.result.status;
  const ocp::GaitProblem& problem = s.solution.problem;
  ASSERT_EQ(problem.variants, 3);
  const double mu = s.nominal.friction();
  for (int v = 0; v < problem.variants; ++v) {
    const gaits::Trajectory t =
        ocp::reconstructDense(problem, s.nominal, s.solution.result.x, 1000.0, 0, v);
    const dynamics::Model& model = v == 0 ? s.nominal : *problem.models[v];
    const double least_normal = gaits::minNormalForce(t);
    const double worst_friction = gaits::maxFrictionRatio(t);
    const double cop = gaits::minFootCopMargin(t, model);
    const double clearance = gaits::minSwingClearance(t, model);
    const double drift = gaits::maxDspTipDrift(t, model);
    RecordProperty(fmt::format("model{}_least_normal_force_N", v),
                   fmt::format("{:.1f}", least_normal));
    RecordProperty(fmt::format("model{}_friction_ratio", v), fmt::format("{:.3f}", worst_friction));
    RecordProperty(fmt::format("model{}_foot_cop_margin_m", v), fmt::format("{:.4f}", cop));
    RecordProperty(fmt::format("model{}_swing_clearance_m", v), fmt::format("{:.2e}", clearance));
    RecordProperty(fmt::format("model{}_dsp_tip_drift_m", v), fmt::format("{:.2e}", drift));
    EXPECT_GT(least_normal, 0) << "model " << v;
    EXPECT_LT(worst_friction, mu) << "model " << v;
    EXPECT_GT(cop, 0) << "model " << v;
    EXPECT_GT(clearance, -1e-6) << "model " << v;
    EXPECT_LT(drift, 1e-6) << "model " << v;
  }
}

/// Issue 33's upright posture, on the nominal's 1 kHz export: torso within 15 degrees of
/// vertical, stance knee flexed at most 45 and swing knee at most 75 degrees over the whole step
/// (the default optimum swings its knee to 92).
TEST_F(EnsembleExport, TheEnsembleOptimumStaysUpright) {
  const Solved& s = ensembleOptimum();
  ASSERT_TRUE(s.solution.result.success) << s.solution.result.status;
  constexpr double kDeg = std::numbers::pi / 180;
  const gaits::Posture p = gaits::posture(s.dense, s.nominal);
  RecordProperty("posture_deg", fmt::format("{:.1f} {:.1f} {:.1f}", p.torso_lean / kDeg,
                                            p.stance_knee / kDeg, p.swing_knee / kDeg));
  EXPECT_LT(p.torso_lean, 15 * kDeg);
  EXPECT_LT(p.stance_knee, 45 * kDeg);
  EXPECT_LT(p.swing_knee, 75 * kDeg);
}

/// Contact between the points (ocp/problem/interior_contact.hpp): a copy whose computed-torque
/// law computes with Mu's case 2 (+40 % masses and inertias, +10 % lengths) on the nominal plant,
/// at 15 single-support segments. Its contact rows at the points alone let its 1 kHz export pull
/// on the ground between them (-58 N 4 ms after a point at 30 segments; at 15 the solve did not
/// converge in 6658 iterations); held also at 6 interior samples of every segment, every model's
/// export keeps its tips loaded and inside the cone.
TEST_F(EnsembleExport, AModelOffByMusCaseTwoStaysOnTheGroundBetweenThePoints) {
  ocp::OcpConfig config =
      ocp::loadOcpConfig(std::string(GAITOPT_SOURCE_DIR) + "/configs/ocp/mu2004_walk_ensemble.yaml",
                         {config::parseOverride("variants=[{controller_case: 2}]"),
                          config::parseOverride("phases[0].segments=15"),
                          config::parseOverride("constraints.interior_contact=8")});
  config.solver.progress = false;
  const dynamics::Model nominal = dynamics::loadRobot(config.robot_path);
  const ocp::GaitSolution s =
      ocp::solveGait(nominal, config, ocp::polynomialGuess(nominal, config));
  ASSERT_TRUE(s.result.success) << s.result.status;
  const double cone = nominal.friction() - config.friction_margin;
  for (int v = 0; v < s.problem.variants; ++v) {
    const gaits::Trajectory t = ocp::reconstructDense(s.problem, nominal, s.result.x, 1000.0, 0, v);
    RecordProperty(fmt::format("model{}_least_normal_force_N", v),
                   fmt::format("{:.1f}", gaits::minNormalForce(t)));
    EXPECT_GT(gaits::minNormalForce(t), 0.6 * config.min_normal_force) << "model " << v;
    EXPECT_LT(gaits::maxFrictionRatio(t), cone + 0.01) << "model " << v;
  }
}

/// The plants of the walk test, one instantiation.
std::vector<Plant> plants() {
  std::vector<Plant> p{{"rigid", -0.2}, {"rigid", -0.1},     {"rigid", 0.1},
                       {"rigid", 0.2},  {"rigid", 0, -0.05}, {"lcp", -0.1}};
#ifdef GAITOPT_HAS_DART
  p.insert(p.end(), {{"dart", -0.1}, {"dart", 0.0}, {"dart", 0.1}});
#endif
  return p;
}

std::string plantName(const ::testing::TestParamInfo<Plant>& info) {
  const auto named = [&](double error, const char* below, const char* above) {
    const long percent = std::lround(100 * error);
    return fmt::format("{}_{}{}", info.param.ground, percent < 0 ? below : above,
                       std::labs(percent));
  };
  if (info.param.length_error != 0) return named(info.param.length_error, "shorter", "longer");
  if (info.param.mass_error == 0) return fmt::format("{}_nominal", info.param.ground);
  return named(info.param.mass_error, "lighter", "heavier");
}

INSTANTIATE_TEST_SUITE_P(Plants, EnsembleWalk, ::testing::ValuesIn(plants()), plantName);

}  // namespace
}  // namespace gaitopt::sim
