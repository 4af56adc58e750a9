// Model variants driven by the closed loop's own computed-torque law (variant_feedback: {law:
// computed_torque}, ocp/shape/computed_torque_law.hpp). At the solution of a small ensemble,
// every single-support torque of the variant is recomputed by the controller the walks use
// (sim::TrackingController with its PD law, on the nominal model or on one off by Mu's case):
// the optimiser's law and the controller's must be the same function. The variant's points satisfy
// its own (heavier) model's dynamics, so the pair is the closed loop on that plant, collocated.
// Config errors name their key.
#include <gtest/gtest.h>

#include <memory>

#include <fmt/format.h>

#include "dynamics/kinematics.hpp"
#include "dynamics/model_variation.hpp"
#include "dynamics/ssp_dynamics.hpp"
#include "gaits/export/export_checks.hpp"
#include "ocp/shape/computed_torque_law.hpp"
#include "sim/controllers/tracking_controller.hpp"
#include "sim/controllers/tracking_law.hpp"
#include "support/solved_config.hpp"

namespace gaitopt::ocp {
namespace {

constexpr double kKp = 400, kKd = 40;  // the tracking law's defaults [1/s^2], [1/s]

std::vector<config::Override> ensemble(const std::string& feedback,
                                       const std::string& variant = "{mass_scale: 1.1}") {
  std::vector<config::Override> o;
  for (const std::string& s :
       {"variants=[" + variant + "]", "variant_feedback=" + feedback,
        std::string("variant_end_tolerance=0.05"), std::string("phases[0].segments=15"),
        std::string("phases[1].segments=3"), std::string("solver.linear_solver=mumps")})
    o.push_back(config::parseOverride(s));
  return o;
}

const std::string kLaw = "{law: computed_torque, kp: 400, kd: 40, dsp_kp: 300, dsp_kd: 30}";

std::string loadError(const std::string& feedback,
                      const std::string& variant = "{mass_scale: 1.1}") {
  try {
    loadOcpConfig(test::shippedOcpConfig("mu2004_walk"), ensemble(feedback, variant));
  } catch (const std::exception& e) {
    return e.what();
  }
  return "";
}

TEST(ComputedTorqueVariantConfig, TheLawAndItsGainsAreReadStrictly) {
  EXPECT_EQ(loadError(kLaw), "");
  EXPECT_NE(loadError("{law: computed_torque, kp: 400, kd: 40}").find("dsp_kp"), std::string::npos);
  EXPECT_NE(loadError("{law: lqr, kp: 400, kd: 40}").find("variant_feedback.law"),
            std::string::npos);
  EXPECT_NE(
      loadError("{kp: 300, kd: 30, dsp_kp: 300}").find("only meaningful with law: computed_torque"),
      std::string::npos);
}

TEST(ComputedTorqueVariantConfig, APassiveJointIsRefused) {
  const dynamics::Model rabbit =
      problemModel(loadOcpConfig(test::shippedOcpConfig("rabbit_kelly2017")));
  FeedbackGains g;
  g.kp = kKp;
  g.kd = kKd;
  EXPECT_THROW(ComputedTorqueResidual(rabbit, g), std::invalid_argument);
}

/// A variant (shape_config.hpp VariantConfig), its plant's mass and length scales and the
/// controller's case.
struct VariantCase {
  std::string yaml;
  double mass_scale;
  double length_scale;
  int controller_case;
};

class ComputedTorqueVariant : public ::testing::TestWithParam<VariantCase> {};

// The 10 % heavier plant and the plant with 5 % longer links under the controller's nominal
// model, and the nominal plant under a controller whose model is off by Mu's case 2 (+40 % masses
// and inertias, +10 % lengths). Each copy lands where its own legs put its tip.
TEST_P(ComputedTorqueVariant, TorquesAreTheTrackingControllersOnItsModel) {
#ifndef NDEBUG
  GTEST_SKIP() << "a solve: optimised builds only";
#endif
  const VariantCase& c = GetParam();
  const test::SolvedConfig s(
      loadOcpConfig(test::shippedOcpConfig("mu2004_walk"), ensemble(kLaw, c.yaml)));
  ASSERT_TRUE(s.result.success) << s.result.status;
  const dynamics::Model model =
      c.controller_case == 1
          ? s.model
          : dynamics::perturbedModel(s.model, dynamics::muUncertaintyCase(c.controller_case));
  const sim::TrackingController controller(model, std::make_shared<sim::PdLaw>(kKp, kKd));
  const double e = c.mass_scale - 1, el = c.length_scale - 1;
  const dynamics::Model plant =
      dynamics::perturbedModel(s.model, {.mass = e, .inertia = e, .length = el, .com = el});
  const Phase& variant = *s.problem.phasesOf(0, 1)[0];
  const Phase& reference = *s.problem.phasesOf(0, 0)[0];
  const PointLayout& l = variant.point;
  double law_error = 0, own_model = 0, correction = 0;
  for (int k = 0; k < variant.layout.points(); ++k) {
    const Eigen::VectorXd pv = variant.layout.point(s.result.x, k);
    const Eigen::VectorXd pr = reference.layout.point(s.result.x, k);
    gaits::Knot ref;
    ref.theta = l.q.of(pr);
    ref.dtheta = l.v.of(pr);
    ref.ddtheta = l.a.of(pr);
    const VecD theta = l.q.of(pv), dtheta = l.v.of(pv), tau = l.u.of(pv);
    const VecD commanded = controller.unclippedTorque(gaits::Phase::kSsp, theta, dtheta, ref);
    law_error = std::max(law_error, (commanded - tau).cwiseAbs().maxCoeff());
    own_model = std::max(
        own_model, (dynamics::sspInverseDynamics(plant, theta, dtheta, VecD(l.a.of(pv))) - tau)
                       .cwiseAbs()
                       .maxCoeff());
    correction = std::max(correction, (tau - VecD(l.u.of(pr))).cwiseAbs().maxCoeff());
  }
  RecordProperty("largest_law_error_Nm", fmt::format("{:.3g}", law_error));
  RecordProperty("largest_correction_Nm", fmt::format("{:.3g}", correction));
  EXPECT_LT(law_error, 1e-6);  // the controller's torque, to the solver's tolerance
  EXPECT_LT(own_model, 1e-6);  // on the plant's dynamics
  EXPECT_GT(correction, 1.0);  // and it is not the reference's feed-forward
  const Eigen::VectorXd strike = variant.layout.point(s.result.x, variant.layout.points() - 1);
  const Vec2d tip = dynamics::swingTip<double>(plant, VecD(l.q.of(strike)));
  EXPECT_NEAR(tip.x(), s.config.step_length * c.length_scale, 1e-6);
  EXPECT_NEAR(tip.y(), 0.0, 1e-6);
}

INSTANTIATE_TEST_SUITE_P(PlantOrController, ComputedTorqueVariant,
                         ::testing::Values(VariantCase{"{mass_scale: 1.1}", 1.1, 1.0, 1},
                                           VariantCase{"{length_scale: 1.05}", 1.0, 1.05, 1},
                                           VariantCase{"{controller_case: 2}", 1.0, 1.0, 2}));

/// A copy with longer links steps farther, and its double support in reduced coordinates pins
/// its tip there: its 1 kHz export must stay on that point between the collocation points too
/// (exported on the nominal's step, the chart moved the copy's tip by its 5 % of the step).
TEST(ComputedTorqueVariantExport, ALongerCopysDoubleSupportStaysOnItsOwnStep) {
#ifndef NDEBUG
  GTEST_SKIP() << "a solve: optimised builds only";
#endif
  std::vector<config::Override> o = ensemble(kLaw, "{length_scale: 1.05}");
  o.push_back(config::parseOverride("constraints.dsp_reduced_coordinates=true"));
  const test::SolvedConfig s(loadOcpConfig(test::shippedOcpConfig("mu2004_walk"), o));
  ASSERT_TRUE(s.result.success) << s.result.status;
  const dynamics::Model plant =
      dynamics::perturbedModel(s.model, {.mass = 0, .inertia = 0, .length = 0.05, .com = 0.05});
  const gaits::Trajectory copy = reconstructDense(s.problem, s.model, s.result.x, 1000.0, 0, 1);
  EXPECT_NEAR(copy.stepLength(), 1.05 * s.config.step_length, 1e-12);
  EXPECT_LT(gaits::maxDspTipDrift(copy, plant), 1e-9);
}

TEST(ComputedTorqueVariantConfig, AVariantIsReadStrictly) {
  EXPECT_EQ(loadError(kLaw, "{mass_scale: 0.9, controller_case: 3}"), "");
  EXPECT_NE(loadError(kLaw, "{controller_case: 4}").find("controller_case"), std::string::npos);
  EXPECT_NE(loadError(kLaw, "{controller_case: 2.5}").find("controller_case"), std::string::npos);
  EXPECT_NE(loadError(kLaw, "{controller_case: 1}").find("differs from the nominal"),
            std::string::npos);
  EXPECT_EQ(loadError(kLaw, "{length_scale: 0.95}"), "");
  EXPECT_NE(loadError(kLaw, "{length_scale: 1.5}").find("length_scale"), std::string::npos);
}

}  // namespace
}  // namespace gaitopt::ocp
