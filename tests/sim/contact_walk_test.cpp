// Contact that is physical: the free-base contact dynamics reduce to Mu's pinned
// models and obey Newton's law while a tip slides; the stance ankle saturates where the CoP
// reaches the edge of the foot; on rigid ground a small slip is measured and the walk goes on,
// a large one ends it, and the polynomial gait (ZMP 0.147 m off the foot) fails as a foot
// rotation when the rules say so.
#include <gtest/gtest.h>

#include "dynamics/centre_of_pressure.hpp"
#include "dynamics/dsp_dynamics.hpp"
#include "dynamics/ground.hpp"
#include "dynamics/model_variation.hpp"
#include "dynamics/ssp_dynamics.hpp"
#include "five_link_gait.hpp"
#include "sim/contact/contact_dynamics.hpp"
#include "sim/walk/hybrid_walk.hpp"
#include "sim/walk/rigid_contact_loop.hpp"

namespace gaitopt::sim {
namespace {

using gaits::Phase;

const gaits::Knot& midSsp() {
  const auto& knots = test::polynomialGait().knots();
  return knots[knots.size() / 3];
}

TEST(ContactDynamics, StickingTipsAreMusPinnedModels) {
  const dynamics::Model& m = test::fiveLinkRobot();
  const gaits::Knot& k = midSsp();
  const VecD theta = k.theta, dtheta = k.dtheta, tau = k.tau;
  const auto ssp =
      contactDynamics(m, theta, dtheta, tau, {TipContact::stick(), TipContact::free()});
  EXPECT_LT((VecD(ssp.qddot.tail(5)) - dynamics::sspForwardDynamics(m, theta, dtheta, tau))
                .cwiseAbs()
                .maxCoeff(),
            1e-9);
  EXPECT_LT(ssp.qddot.head(2).norm(), 1e-9);  // B pinned
  const auto dsp =
      contactDynamics(m, theta, dtheta, tau, {TipContact::stick(), TipContact::stick()});
  const auto pinned = dynamics::dspForwardDynamics(m, theta, dtheta, tau);
  EXPECT_LT((VecD(dsp.qddot.tail(5)) - pinned.ddtheta).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_LT((dsp.force_e - pinned.force_swing).norm(), 1e-7);
}

TEST(ContactDynamics, ASlidingTipTakesMuNAgainstItsSlipAndNewtonHolds) {
  const dynamics::Model m = dynamics::withFriction(test::fiveLinkRobot(), 0.2);
  const gaits::Knot& k = midSsp();
  const VecD theta = k.theta, dtheta = k.dtheta;
  for (double s : {1.0, -1.0}) {
    const auto a =
        contactDynamics(m, theta, dtheta, VecD(k.tau), {TipContact::slide(s), TipContact::free()});
    EXPECT_NEAR(a.force_b(0), -s * 0.2 * a.force_b(1), 1e-9);
    EXPECT_NEAR(a.qddot(1), 0.0, 1e-9);  // held on the ground
    // Total linear momentum: m (a_com - g_vec) = F_B, with a_com of the free base.
    const VecD ddtheta = a.qddot.tail(5);
    const Vec2d a_com = a.qddot.head<2>() +
                        dynamics::pointAcceleration(m.totalComWeights(), theta, dtheta, ddtheta);
    EXPECT_LT((m.totalMass() * (a_com - m.gravityAcceleration()) - a.force_b).norm(), 1e-8);
  }
}

/// A controller that asks the ankle for a fixed torque, the reference's elsewhere.
class AnkleDemand : public Controller {
 public:
  explicit AnkleDemand(double tau0) : tau0_(tau0) {}
  VecD torque(Phase, const VecD&, const VecD&, const gaits::Knot& ref,
              const Eigen::VectorXd&) const override {
    VecD tau = ref.tau;
    tau(0) = tau0_;
    return tau;
  }

 private:
  double tau0_;
};

TEST(AnkleSaturation, TheCopStopsAtTheHeelAndTheToe) {
  const dynamics::Model& m = test::fiveLinkRobot();
  const Reference ref(test::polynomialGait());
  const gaits::Knot& k = midSsp();
  const Eigen::VectorXd x = contactState(k.theta, k.dtheta);
  // tau0 > 0 puts the CoP -tau0 / F_y behind B: at the heel; tau0 < 0 at the toe.
  for (const auto& [demand, edge] : {std::pair{100.0, -m.foot().heel}, {-100.0, m.foot().toe}}) {
    const AnkleDemand controller(demand);
    const ContactLoop loop(m, controller, ref, Phase::kSsp, {}, ContactSet{}, ContactRules{});
    const auto& s = loop.at(k.t, x);
    EXPECT_TRUE(s.saturated);
    // The CoP of the ground wrench the plant felt, by ground.hpp's definition.
    EXPECT_NEAR(
        dynamics::centreOfPressure<double>(0.0, s.force_stance, -s.tau(0), 0.0, Vec2d::Zero()),
        edge, 1e-9);
    ContactRules fail;
    fail.cop_limit = CopLimit::kFail;
    const ContactLoop strict(m, controller, ref, Phase::kSsp, {}, ContactSet{}, fail);
    EXPECT_EQ(strict.at(k.t, x).tau(0), demand);  // not clipped: the walk fails instead
  }
}

/// The polynomial gait under computed torque on rigid ground; the long-heel robot unless `robot`.
WalkResult rigidWalk(double friction, int steps, const ContactRules& rules = {},
                     const dynamics::Model& robot = test::longHeelRobot()) {
  const dynamics::Model plant = dynamics::withFriction(robot, friction);
  WalkOptions o;
  o.steps = steps;
  o.rules = rules;
  return simulateWalk(plant, test::computedTorque(), Reference(test::polynomialGait()), o);
}

TEST(RigidSlip, ASmallSlipIsMeasuredAndTheWalkGoesOn) {
  const WalkResult w = rigidWalk(0.29, 3);
  RecordProperty("max_slip_m", std::to_string(w.max_slip));
  EXPECT_EQ(w.steps_completed, 3) << w.failure;
  EXPECT_GT(w.max_slip, 0.0);
  EXPECT_LT(w.max_slip, 0.01);
}

TEST(RigidSlip, ASlipBeyondTheLimitEndsTheWalk) {
  const WalkResult w = rigidWalk(0.05, 3);
  EXPECT_LT(w.steps_completed, 3);
  EXPECT_NE(w.failure.find(kSlip), std::string::npos) << w.failure;
}

// The share of Coulomb's cone a walk records (contact_rules.hpp loadedFrictionRatio) is near the
// one its gait asks for while the tips stick, read off the gait's own knots; a tip that slides
// uses the whole cone.
TEST(FrictionRatio, AStickingWalkUsesTheShareItsGaitAsksAndASlidingOneTheWholeCone) {
  const dynamics::Model& robot = test::longHeelRobot();
  const double weight = robot.totalMass() * robot.gravity();
  double asked = 0;
  for (const gaits::Knot& k : test::polynomialGait().knots())
    asked = std::max({asked, loadedFrictionRatio(k.force_stance, weight),
                      loadedFrictionRatio(k.force_swing, weight)});
  const WalkResult sticking = rigidWalk(1.0, 3);
  ASSERT_EQ(sticking.steps_completed, 3) << sticking.failure;
  // Measured 0.289 against the gait's 0.311, both at the double support's start: there the
  // walk's tips take 33.8 and -39.0 N along the ground where the gait's take 30.5 and -42.0 N,
  // at the same normal forces (154.5 and 135.0 N).
  EXPECT_NEAR(sticking.max_friction_ratio, asked, 0.03);
  // Below the 0.289 that walk used, a tip slides at the cone's edge until the slip ends the walk.
  const WalkResult sliding = rigidWalk(0.25, 3);
  ASSERT_NE(sliding.failure.find(kSlip), std::string::npos) << sliding.failure;
  EXPECT_DOUBLE_EQ(sliding.max_friction_ratio, 0.25);
}

TEST(RigidSlip, AStanceTipLeftSlidingByAnImpactSlidesUntilItSticks) {
  const Reference ref(test::polynomialGait());
  const auto step = [&](double v, const ContactRules& rules) {
    return simulateStep(test::longHeelRobot(), test::computedTorque(), ref, ref.start().theta,
                        ref.start().dtheta, {}, {}, 0, 0, 0, {}, rules, v);
  };
  const StepResult nominal = step(0, {}), small = step(0.05, {});
  ASSERT_TRUE(small.ok) << small.failure;
  EXPECT_GT(small.slip, 0.0);
  EXPECT_LT(small.slip, 0.01);
  // B slid forward before it stuck: E lands further ahead of where B started, by the slip.
  EXPECT_NEAR(small.advance - nominal.advance, small.slip, 0.2 * small.slip);
  ContactRules strict;
  strict.max_slip = small.slip / 2;
  const StepResult beyond = step(0.05, strict);
  EXPECT_FALSE(beyond.ok);
  EXPECT_EQ(beyond.failure, kSlip);
}

TEST(FootRotation, ThePolynomialGaitAsksMoreOfTheAnkleThanItsFootCarries) {
  ContactRules fail;
  fail.cop_limit = CopLimit::kFail;
  const WalkResult strict = rigidWalk(0.6, 20, fail, test::fiveLinkRobot());
  RecordProperty("foot_rotation_failure", strict.failure);
  EXPECT_EQ(strict.steps_completed, 0);
  EXPECT_NE(strict.failure.find(kFootRotation), std::string::npos) << strict.failure;
  const WalkResult saturated = rigidWalk(0.6, 2, {}, test::fiveLinkRobot());
  RecordProperty("min_cop_margin_m", std::to_string(saturated.min_cop_margin));
  EXPECT_LT(saturated.min_cop_margin, -0.05);  // the demanded CoP leaves the foot
  EXPECT_GT(saturated.cop_saturated_time, 0.0);
}

}  // namespace
}  // namespace gaitopt::sim
