// The problem's shape (ocp/shape/gait_shape.hpp) and the stage structure the builder records on
// the built problem (ocp/shape/stage_structure.hpp): the stages' columns and rows partition the
// NLP, and every Jacobian and Hessian entry that crosses from one stage to another crosses a
// coupling the builder declared, for the shipped one-step problems, two steps and three model
// variants alike.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "config/config_error.hpp"
#include "ocp/guess/initial_guess.hpp"
#include "ocp/problem/gait_problem.hpp"
#include "support/solved_config.hpp"

namespace gaitopt::ocp {
namespace {

OcpConfig config(const std::string& name, const std::vector<std::string>& sets = {}) {
  std::vector<config::Override> overrides;
  for (const auto& s : sets) overrides.push_back(config::parseOverride(s));
  return loadOcpConfig(test::shippedOcpConfig(name), overrides);
}

/// The five-link walk with two model variants, on a coarse mesh.
OcpConfig variants() {
  return config("mu2004_walk", {"phases[0].segments=6", "phases[1].segments=2",
                                "variants=[{mass_scale: 0.95}, {mass_scale: 1.05}]",
                                "variant_feedback={kp: 300, kd: 30}", "variant_end_tolerance=0.1",
                                "variant_spread=1"});
}

struct Built {
  explicit Built(OcpConfig c)
      : config(std::move(c)),
        model(problemModel(config)),
        problem(buildGaitProblem(model, config, initialGuess(model, config))) {}
  OcpConfig config;
  dynamics::Model model;
  GaitProblem problem;
};

/// Ranges that tile [0, size) in order, empty ones allowed.
template <class Get>
void expectTiled(const StageStructure& s, int size, Get range, const char* what) {
  int next = 0;
  for (const Stage& stage : s.stages) {
    const IndexRange r = range(stage);
    EXPECT_EQ(r.first, next) << stage.name << ": " << what << " do not follow the last stage's";
    next = r.end();
  }
  EXPECT_EQ(next, size) << what << " not all owned by a stage";
}

void expectPartitionAndCouplings(const GaitProblem& p) {
  const StageStructure& s = p.stages;
  const Nlp& nlp = p.nlp;
  expectTiled(
      s, nlp.variables(), [](const Stage& st) { return st.columns; }, "columns");
  expectTiled(
      s, nlp.constraints(), [](const Stage& st) { return st.rows; }, "rows");
  const Eigen::VectorXd x = nlp.initialGuess();
  int crossing = 0;
  for (const auto& e : nlp.jacobianTriplets(x)) {
    const int a = s.stageOfRow(e.row()), b = s.stageOfColumn(e.col());
    crossing += a != b;
    EXPECT_TRUE(s.coupled(a, b)) << "row " << e.row() << " of " << s.stages[a].name
                                 << " reaches column " << e.col() << " of " << s.stages[b].name;
  }
  const Eigen::VectorXd lambda = Eigen::VectorXd::Ones(nlp.constraints());
  for (const auto& e : nlp.hessianTriplets(x, 1.0, lambda)) {
    const int a = s.stageOfColumn(e.row()), b = s.stageOfColumn(e.col());
    EXPECT_TRUE(s.coupled(a, b)) << "Hessian (" << e.row() << ", " << e.col() << ") joins "
                                 << s.stages[a].name << " and " << s.stages[b].name;
  }
  EXPECT_GT(crossing, 0) << "a gait's stages are coupled";
}

std::vector<std::string> names(const StageStructure& s) {
  std::vector<std::string> out;
  for (const Stage& stage : s.stages) out.push_back(stage.name);
  return out;
}

TEST(StageStructure, TheDefaultFiveLinkProblemIsSspTouchdownDspAndItsLinks) {
  const Built b(config("mu2004_walk"));
  const StageStructure& s = b.problem.stages;
  EXPECT_EQ(names(s), (std::vector<std::string>{"ssp", "touchdown", "dsp", "touchdown_to_dsp",
                                                "periodicity"}));
  // The SSP's columns are exactly its points (fixed duration): 61 points of the five-link layout.
  const Phase& ssp = b.problem.ssp;
  EXPECT_EQ(s.stages[0].columns.first, ssp.layout.offset);
  EXPECT_EQ(s.stages[0].columns.size, ssp.layout.points() * ssp.layout.pointSize());
  EXPECT_EQ(ssp.layout.points(), 61);
  // The touchdown owns the double impact's variables: qdot+ (2 + 5) and two impulses (2 + 2).
  EXPECT_EQ(s.stages[1].columns.size, 11);
  // Transitions own rows only: a state of 2 n = 10 rows each.
  for (int t : {3, 4}) {
    EXPECT_EQ(s.stages[t].columns.size, 0);
    EXPECT_EQ(s.stages[t].rows.size, 10);
  }
  expectPartitionAndCouplings(b.problem);
}

TEST(StageStructure, FreeDurationsAndStepDurationStayInsideTheirStages) {
  const Built b(config("mu2004_walk_cot"));
  EXPECT_EQ(names(b.problem.stages).back(), "step_duration");
  expectPartitionAndCouplings(b.problem);
}

TEST(StageStructure, TwoStepsRepeatTheStepAndCloseThePeriodAfterTheSecond) {
  const Built b(config("compass_gait_passive", {"steps=2"}));
  EXPECT_EQ(names(b.problem.stages),
            (std::vector<std::string>{"ssp", "touchdown", "step2_ssp", "step2_touchdown",
                                      "step2_start", "periodicity"}));
  EXPECT_EQ(b.problem.stages.stages[2].step, 1);
  expectPartitionAndCouplings(b.problem);
}

/// The stage of the nominal phase that `b` (a variant's phase) copies.
int nominalStage(const GaitProblem& p, const BuiltPhase& b) {
  for (const BuiltPhase& n : p.built)
    if (n.variant == 0 && n.step == b.step && n.phase.kind == b.phase.kind)
      return p.stages.stageOfColumn(n.phase.layout.offset);
  return -1;
}

TEST(StageStructure, VariantsCopyThePhasesAndMeetTheNominalAtItsStartEndAndClock) {
  const Built b(variants());
  const StageStructure& s = b.problem.stages;
  EXPECT_EQ(b.problem.variants, 3);
  int variant_phases = 0;
  for (size_t i = 0; i < s.stages.size(); ++i) {
    const Stage& stage = s.stages[i];
    if (stage.kind != StageKind::kPhase || stage.variant == 0) continue;
    ++variant_phases;
    // A variant's phase meets the nominal phase it copies (the feedback law).
    const BuiltPhase& phase = b.problem.built[static_cast<size_t>(stage.phase)];
    EXPECT_EQ(phase.variant, stage.variant);
    EXPECT_TRUE(s.coupled(static_cast<int>(i), nominalStage(b.problem, phase))) << stage.name;
  }
  EXPECT_EQ(variant_phases, 4);
  const std::vector<std::string> all = names(s);
  for (const std::string name : {"variant1_start", "variant1_end", "variant2_start", "variant2_end",
                                 "variant2_touchdown_to_dsp", "variant2_touchdown"})
    EXPECT_NE(std::find(all.begin(), all.end(), name), all.end()) << name;
  expectPartitionAndCouplings(b.problem);
}

/// The message of loading the five-link config with `sets`, "" when it loads.
std::string stageLoadError(const std::vector<std::string>& sets) {
  try {
    config("mu2004_walk", sets);
  } catch (const config::ConfigError& e) {
    return e.what();
  }
  return "";
}

TEST(ShapeConfig, ReadsStepsAndVariantsAndRefusesAnIncompleteEnsemble) {
  const OcpConfig c = variants();
  EXPECT_EQ(c.shape.steps, 1);
  ASSERT_EQ(c.shape.variants.size(), 2u);
  EXPECT_EQ(c.shape.variants[1].mass_scale, 1.05);
  EXPECT_EQ(c.shape.feedback.kp, 300);
  EXPECT_EQ(c.shape.feedback.kd, 30);
  EXPECT_EQ(c.shape.end_tolerance, 0.1);
  EXPECT_EQ(c.shape.spread, 1);
  EXPECT_TRUE(c.shape.contact);  // copies keep their contact rows unless told
  EXPECT_EQ(config("mu2004_walk").shape.variantCount(), 1);
  EXPECT_NE(stageLoadError({"steps=1.5"}).find("key 'steps'"), std::string::npos);
  // A variant without the law would have free torques: the ensemble would say nothing.
  const std::string no_law = stageLoadError({"variants=[{mass_scale: 1.1}]"});
  EXPECT_NE(no_law.find("variant_feedback"), std::string::npos) << no_law;
  const std::string stray = stageLoadError({"variant_end_tolerance=0.1"});
  EXPECT_NE(stray.find("only meaningful with `variants`"), std::string::npos) << stray;
  const std::string stray_probe = stageLoadError({"variant_contact=false"});
  EXPECT_NE(stray_probe.find("variant_contact"), std::string::npos) << stray_probe;
  EXPECT_NE(stageLoadError({"variants=[{mass: 1.1}]"}).find("mass"), std::string::npos);
}

}  // namespace
}  // namespace gaitopt::ocp
