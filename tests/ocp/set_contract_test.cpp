// One contract over every constraint set and cost term of the shipped gait problems
// (configs/ocp/*.yaml, on a coarse mesh: the sets are the same code whatever the segments, and
// the five-link walk with an impactless touchdown, with a ZMP margin and with the DSP in reduced
// coordinates, and the shapes of ocp/shape/gait_shape.hpp: two steps in one period, and model
// variants on fixed and on free durations): outputs fully written, derivatives against the set's
// own central differences, the same sparsity at three random points
// (tests/support/set_contract.hpp). Each set is its own test, named config_set, so a failure
// names the set. A last test shows that the contract catches one perturbed Jacobian entry.
#include <algorithm>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <random>
#include <set>

#include <gtest/gtest.h>

#include "dynamics/model.hpp"
#include "ocp/guess/initial_guess.hpp"
#include "ocp/problem/gait_problem.hpp"
#include "support/set_contract.hpp"

namespace gaitopt::ocp {
namespace {

/// A shipped config's problem; the model outlives the sets that point to it.
struct Shipped {
  OcpConfig config;
  dynamics::Model model;
  GaitProblem problem;
};

constexpr int kSegments = 3;  // per phase

/// One variant beside the nominal (ocp/shape/shape_config.hpp): a second one adds the same sets
/// on a larger decision vector.
std::vector<config::Override> variants() {
  return {config::parseOverride("variants=[{mass_scale: 1.1}]"),
          config::parseOverride("variant_feedback={kp: 200, kd: 20}"),
          config::parseOverride("variant_end_tolerance=0.1"),
          config::parseOverride("variant_spread=0.5")};
}

std::unique_ptr<Shipped> coarseProblem(OcpConfig config) {
  // One model variant: a second one adds the same sets on a larger decision vector (with the
  // shipped ensemble's two the contract took 16.3 s in Release, with one 11.5 s; it is the
  // longest test of the sanitizer build, 268 s there).
  if (config.shape.variants.size() > 1) config.shape.variants.resize(1);
  for (auto& phase : config.phases) {
    phase.segments = kSegments;
    phase.mesh.clear();
  }
  const dynamics::Model model = problemModel(config);
  auto s = std::make_unique<Shipped>(Shipped{config, model, {}});
  s->problem = buildGaitProblem(s->model, s->config, initialGuess(s->model, s->config));
  return s;
}

const std::map<std::string, std::unique_ptr<Shipped>>& shippedProblems() {
  static const auto problems = [] {
    std::map<std::string, std::unique_ptr<Shipped>> all;
    const std::filesystem::path dir = std::filesystem::path(GAITOPT_SOURCE_DIR) / "configs/ocp";
    for (const auto& entry : std::filesystem::directory_iterator(dir))
      if (entry.path().extension() == ".yaml")
        all.emplace(entry.path().stem().string(),
                    coarseProblem(loadOcpConfig(entry.path().string())));
    // The touchdown at rest of Mu ch. 3 (touchdown_at_rest in place of the impact's sets).
    OcpConfig impactless = loadOcpConfig((dir / "mu2004_walk.yaml").string());
    impactless.impact = ImpactModel::kImpactless;
    all.emplace("mu2004_walk_impactless", coarseProblem(impactless));
    // The ZMP and foot-B CoP rows on a foot shortened by constraints.zmp_margin.
    OcpConfig zmp_margin = loadOcpConfig((dir / "mu2004_walk.yaml").string());
    zmp_margin.zmp_margin = 0.03;
    all.emplace("mu2004_walk_zmp_margin", coarseProblem(zmp_margin));
    // The DSP in reduced coordinates (dsp_chart.hpp), with fixed and with free durations, and
    // the jerk-jump and torque-rate bounds (jerk_jump.hpp, torque_rate_limit.hpp) on both.
    for (const std::string name : {"mu2004_walk", "mu2004_walk_cot"}) {
      OcpConfig reduced = loadOcpConfig((dir / (name + ".yaml")).string());
      reduced.dsp_reduced_coordinates = true;
      reduced.jerk_jump_limit = 1e4;  // its T column is met on the free durations
      reduced.torque_rate_limit = 1e3;
      all.emplace(name + "_reduced_dsp", coarseProblem(reduced));
    }
    // Two steps in one period: the second step's sets and the relabelling between the steps.
    all.emplace("compass_gait_passive_two_steps",
                coarseProblem(loadOcpConfig((dir / "compass_gait_passive.yaml").string(),
                                            {config::parseOverride("steps=2")})));
    // Model variants: the feedback law, the start and end conditions and every copied set, on
    // the nominal's fixed durations and on its free ones (with work slacks in the nominal's
    // points only, so the law reads two different point layouts).
    for (const std::string name : {"mu2004_walk", "mu2004_walk_cot"})
      all.emplace(name + "_variants",
                  coarseProblem(loadOcpConfig((dir / (name + ".yaml")).string(), variants())));
    // The closed loop's computed-torque law in single support (computed_torque_law.hpp), with
    // the least normal force on the contact rows, also between the points (interior_contact.hpp).
    std::vector<config::Override> ct = variants();
    ct[1] = config::parseOverride(
        "variant_feedback={law: computed_torque, kp: 400, kd: 40, dsp_kp: 300, dsp_kd: 30}");
    ct.push_back(config::parseOverride("constraints.min_normal_force=50"));
    ct.push_back(config::parseOverride("constraints.interior_contact=4"));
    all.emplace("mu2004_walk_computed_torque_variants",
                coarseProblem(loadOcpConfig((dir / "mu2004_walk.yaml").string(), ct)));
    return all;
  }();
  return problems;
}

struct SetCase {
  std::string config;
  bool cost = false;  ///< a cost term, else a constraint set
  size_t index = 0;
  std::string name;
};

std::vector<SetCase> allSets() {
  std::vector<SetCase> cases;
  for (const auto& [config, s] : shippedProblems()) {
    const Nlp& nlp = s->problem.nlp;
    for (size_t i = 0; i < nlp.constraintSets().size(); ++i)
      cases.push_back({config, false, i, nlp.constraintSets()[i]->name()});
    for (size_t i = 0; i < nlp.costTerms().size(); ++i)
      cases.push_back({config, true, i, nlp.costTerms()[i]->name()});
  }
  return cases;
}

/// Random point i: the guess moved by up to 0.05 in every variable (angles, rates, torques,
/// forces alike: a generic point near the solutions the solver visits).
Eigen::VectorXd randomPoint(const Nlp& nlp, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-0.05, 0.05);
  Eigen::VectorXd x = nlp.initialGuess();
  for (auto& v : x) v += u(rng);
  return x;
}

Eigen::VectorXd randomMultipliers(int rows, unsigned seed) {
  std::mt19937 rng(seed + 100);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::VectorXd lambda(rows);
  for (auto& v : lambda) v = u(rng);
  return lambda;
}

std::string joined(const std::vector<std::string>& broken) {
  std::string out;
  for (const auto& b : broken) out += "\n  " + b;
  return out;
}

class SetContract : public ::testing::TestWithParam<SetCase> {};

TEST_P(SetContract, WritesEveryOutputHasExactDerivativesAndAFixedSparsity) {
  const SetCase& c = GetParam();
  const Nlp& nlp = shippedProblems().at(c.config)->problem.nlp;
  test::RecordedPattern pattern;
  for (unsigned seed = 1; seed <= 3; ++seed) {
    const Eigen::VectorXd x = randomPoint(nlp, seed);
    const auto broken =
        c.cost ? test::checkCostTerm(*nlp.costTerms()[c.index], x, 0.7, pattern)
               : test::checkConstraintSet(
                     *nlp.constraintSets()[c.index], x,
                     randomMultipliers(nlp.constraintSets()[c.index]->rows(), seed), pattern);
    EXPECT_TRUE(broken.empty()) << c.config << ": " << (c.cost ? "cost " : "constraint set ")
                                << c.name << " at random point " << seed << joined(broken);
  }
}

INSTANTIATE_TEST_SUITE_P(ShippedProblems, SetContract, ::testing::ValuesIn(allSets()),
                         [](const ::testing::TestParamInfo<SetCase>& info) {
                           return info.param.config + "_" + info.param.name;
                         });

/// Every set and cost term that the shape builder (ocp/shape/) and touchdown.cpp can add, in
/// each phase it can appear in, is among those the contract runs over.
TEST(SetContractCoverage, EverySetOfTheGaitProblemIsChecked) {
  std::set<std::string> checked;
  for (const SetCase& c : allSets()) checked.insert(c.name);
  for (const char* name : {"ssp_defects",
                           "ssp_dynamics",
                           "ssp_knees",
                           "ssp_ground_contact",
                           "ssp_interior_contact",
                           "ssp_clearance",
                           "ssp_work_split",
                           "dsp_defects",
                           "dsp_chart_defects",
                           "ssp_jerk",
                           "dsp_jerk",
                           "ssp_jerk_jump",
                           "dsp_jerk_jump",
                           "ssp_torque_rate",
                           "dsp_torque_rate",
                           "dsp_pin_1",
                           "dsp_dynamics",
                           "dsp_knees",
                           "dsp_ground_contact",
                           "dsp_work_split",
                           "touchdown_position",
                           "touchdown_at_rest",
                           "strike_downward",
                           "impact",
                           "impulse_cones",
                           "touchdown_to_dsp",
                           "periodicity",
                           "step_duration",
                           "ssp_torque_squared",
                           "dsp_torque_squared",
                           "ssp_abs_work",
                           "dsp_abs_work",
                           "ssp_interior_work_split",
                           "dsp_interior_work_split",
                           "ssp_interior_abs_work",
                           "dsp_interior_abs_work",
                           "step2_ssp_defects",
                           "step2_ssp_dynamics",
                           "step2_ssp_ground_contact",
                           "step2_touchdown_position",
                           "step2_impact",
                           "step2_start",
                           "variant1_ssp_defects",
                           "variant1_ssp_dynamics",
                           "variant1_ssp_ground_contact",
                           "variant1_ssp_clearance",
                           "variant1_ssp_feedback",
                           "variant1_ssp_computed_torque",
                           "variant1_dsp_defects",
                           "variant1_dsp_dynamics",
                           "variant1_dsp_ground_contact",
                           "variant1_dsp_feedback",
                           "variant1_impact",
                           "variant1_impulse_cones",
                           "variant1_touchdown_to_dsp",
                           "variant1_start",
                           "variant1_end",
                           "variant1_ssp_spread",
                           "variant1_dsp_spread"})
    EXPECT_TRUE(checked.count(name)) << name << " is in no problem of the contract";
}

/// The slips a hand-written derivative makes: an entry off by a small amount, or an entry left
/// out (a whole Jacobian column: the set reads a variable its pattern does not name).
enum class Slip {
  kJacobianEntryOff,
  kJacobianColumnLeftOut,
  kHessianEntryOff,
  kHessianEntryLeftOut
};

/// A set with one slip in its derivatives at entry `entry` of its output sequence.
class SlippedSet : public ConstraintSet {
 public:
  SlippedSet(const ConstraintSet& set, Slip slip, size_t entry)
      : ConstraintSet(set.name(), set.rows(), set.phase()),
        set_(&set),
        slip_(slip),
        entry_(entry) {}
  Eigen::VectorXd lowerBounds() const override { return set_->lowerBounds(); }
  Eigen::VectorXd upperBounds() const override { return set_->upperBounds(); }
  void values(const Eigen::VectorXd& x, Eigen::Ref<Eigen::VectorXd> g) const override {
    set_->values(x, g);
  }
  void jacobian(const Eigen::VectorXd& x, Triplets& out) const override {
    Triplets t;
    set_->jacobian(x, t);
    if (slip_ == Slip::kJacobianEntryOff)
      t[entry_] = {t[entry_].row(), t[entry_].col(), t[entry_].value() + 1e-3};
    const int column = t[entry_].col();
    for (const auto& e : t)
      if (slip_ != Slip::kJacobianColumnLeftOut || e.col() != column) out.push_back(e);
  }
  void hessian(const Eigen::VectorXd& x, const Eigen::VectorXd& lambda,
               Triplets& out) const override {
    Triplets t;
    set_->hessian(x, lambda, t);
    if (slip_ == Slip::kHessianEntryOff)
      t[entry_] = {t[entry_].row(), t[entry_].col(), t[entry_].value() + 1e-2};
    if (slip_ == Slip::kHessianEntryLeftOut) t.erase(t.begin() + static_cast<long>(entry_));
    out.insert(out.end(), t.begin(), t.end());
  }

 private:
  const ConstraintSet* set_;
  Slip slip_;
  size_t entry_;
};

/// Each slip in the default problem's SSP dynamics breaks the contract, naming the matrix it is
/// in: the contract differences only the columns a set's pattern names, so a left-out column must
/// be found by its probe of the others (set_contract.hpp, columnsToDifference).
TEST(SetContractSelfTest, EverySlipInADerivativeBreaksTheContract) {
  const Nlp& nlp = shippedProblems().at("mu2004_walk")->problem.nlp;
  const auto& sets = nlp.constraintSets();
  const auto dynamics = std::find_if(sets.begin(), sets.end(),
                                     [](const auto& s) { return s->name() == "ssp_dynamics"; });
  ASSERT_NE(dynamics, sets.end());
  const Eigen::VectorXd x = randomPoint(nlp, 1);
  const Eigen::VectorXd lambda = randomMultipliers((*dynamics)->rows(), 1);
  test::RecordedPattern intact;
  EXPECT_TRUE(test::checkConstraintSet(**dynamics, x, lambda, intact).empty());
  // Entry 7 of each sequence: a residual entry of O(1-100) off by 1e-3, a Hessian one by 1e-2.
  const std::vector<std::pair<Slip, std::string>> slips{{Slip::kJacobianEntryOff, "Jacobian"},
                                                        {Slip::kJacobianColumnLeftOut, "Jacobian"},
                                                        {Slip::kHessianEntryOff, "Hessian"},
                                                        {Slip::kHessianEntryLeftOut, "Hessian"}};
  for (const auto& [slip, matrix] : slips) {
    test::RecordedPattern pattern;
    const auto broken =
        test::checkConstraintSet(SlippedSet(**dynamics, slip, 7), x, lambda, pattern);
    ASSERT_FALSE(broken.empty()) << matrix << " slip " << static_cast<int>(slip);
    EXPECT_NE(broken.front().find(matrix), std::string::npos) << broken.front();
    std::cout << "slip " << static_cast<int>(slip) << " in ssp_dynamics:" << joined(broken) << '\n';
  }
}

}  // namespace
}  // namespace gaitopt::ocp
