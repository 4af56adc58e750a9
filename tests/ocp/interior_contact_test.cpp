// The single support's contact rows between the collocation points
// (ocp/problem/interior_contact.hpp). The rows are ground_contact's on the export's own reading of
// a segment, so at a generic point of the decision space they equal GroundContact evaluated at
// exportPoint (collocation_interpolation.hpp, what the 1 kHz export and a controller read) at
// every sample time. Their derivatives are checked by the set contract (set_contract_test.cpp).
// Solved, they keep a model variant driven by a computed-torque law on a model off by Mu's
// case 2 on the ground between the points: at the points alone its export pulled on the ground.
#include <gtest/gtest.h>

#include <random>

#include "gaits/export/export_checks.hpp"
#include "ocp/guess/initial_guess.hpp"
#include "ocp/problem/gait_problem.hpp"
#include "ocp/problem/ground_contact.hpp"
#include "ocp/solve/gait_solve.hpp"
#include "ocp/transcription/collocation_interpolation.hpp"

namespace gaitopt::ocp {
namespace {

const std::string kConfigs = std::string(GAITOPT_SOURCE_DIR) + "/configs/ocp/";
constexpr int kSubIntervals = 8;

TEST(InteriorContact, ReadsTheContactRowsOnTheExportsPolynomials) {
  const OcpConfig c = loadOcpConfig(kConfigs + "mu2004_walk.yaml",
                                    {config::parseOverride("constraints.interior_contact=8"),
                                     config::parseOverride("constraints.zmp_margin=0.02"),
                                     config::parseOverride("constraints.min_normal_force=20")});
  const dynamics::Model model = problemModel(c);
  const GaitProblem problem = buildGaitProblem(model, c, initialGuess(model, c));
  const ConstraintSet* rows = nullptr;
  for (const auto& set : problem.nlp.constraintSets())
    if (set->name() == "ssp_interior_contact") rows = set.get();
  ASSERT_NE(rows, nullptr);
  const Phase& ssp = *problem.phasesOf(0, 0)[0];
  const GroundContact contact(model, ssp.point, marginFoot(model, c), c.step_length,
                              frictionBound(model, c), c.min_normal_force);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-0.05, 0.05);
  Eigen::VectorXd x = problem.nlp.initialGuess();
  for (auto& v : x) v += u(rng);
  Eigen::VectorXd g(rows->rows());
  rows->values(x, g);
  const int m = contact.rows(), samples = kSubIntervals - 2;
  ASSERT_EQ(rows->rows(), ssp.layout.segments * samples * m);
  EXPECT_EQ(rows->lowerBounds().head(m), contact.lowerBounds());
  Eigen::VectorXd expected(m);
  double worst = 0;
  for (int k = 0; k < ssp.layout.segments; ++k) {
    const double t0 = ssp.layout.time(2 * k), h = ssp.layout.time(2 * k + 2) - t0;
    for (int r = 0, i = 1; i < kSubIntervals; ++i) {
      if (2 * i == kSubIntervals) continue;  // the midpoint is a point: ground_contact's
      contact.evaluate(exportPoint(ssp.layout, x, t0 + h * i / kSubIntervals), expected);
      const Eigen::VectorXd got = g.segment((k * samples + r++) * m, m);
      worst = std::max(
          worst, (got - expected).cwiseAbs().maxCoeff() / (1 + expected.cwiseAbs().maxCoeff()));
    }
  }
  EXPECT_LT(worst, 1e-12);
}

TEST(InteriorContact, RefusesWhatItCannotRead) {
  const auto error = [](const std::string& file, const std::string& value) -> std::string {
    try {
      loadOcpConfig(kConfigs + file,
                    {config::parseOverride("constraints.interior_contact=" + value)});
    } catch (const std::exception& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_EQ(error("mu2004_walk.yaml", "8"), "");
  EXPECT_NE(error("mu2004_walk.yaml", "3").find("interior_contact"), std::string::npos);
  EXPECT_NE(error("mu2004_walk.yaml", "2").find("interior_contact"), std::string::npos);
  // Free durations: refused as the config is read, by key, not when the problem is built.
  EXPECT_NE(error("mu2004_walk_cot.yaml", "8")
                .find("key 'constraints.interior_contact': needs scheme: hermite_simpson and "
                      "phases of fixed duration"),
            std::string::npos);
}

}  // namespace
}  // namespace gaitopt::ocp
