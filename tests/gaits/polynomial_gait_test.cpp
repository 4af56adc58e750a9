// The polynomial gait of Mu (2004) ch. 3: boundary conditions (3.2-3.23), inverse kinematics
// (3.24) against Table 4.1, continuity and periodicity, and zero touchdown velocity.
#include <algorithm>
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "config/config_error.hpp"
#include "config/overrides.hpp"
#include "dynamics/impact/relabel.hpp"
#include "dynamics/kinematics.hpp"
#include "gaits/export/metrics.hpp"
#include "gaits/polynomial/polynomial_gait.hpp"
#include "support/fixtures.hpp"

namespace gaitopt::test {
namespace {

using gaits::Phase;

gaits::GaitParams muParams() {
  return gaits::loadGait(std::string(GAITOPT_SOURCE_DIR) + "/configs/gaits/mu2004.yaml");
}

class PolynomialGaitTest : public ::testing::Test {
 protected:
  dynamics::Model model_ = loadNamed("mu2004_five_link");
  gaits::GaitParams params_ = muParams();
  gaits::HipPlan plan_{0.4, 0.55, 0.16, params_.hip_start, params_.hip_height};
  gaits::PolynomialGait gait_{model_, params_, plan_};
};

TEST_F(PolynomialGaitTest, SwingTipMatchesMuCoefficients) {
  // docs/derivations.md#the-polynomial-gait: a = (-0.35, 0, 5.8333, -6.4815), b = (0, 0, 2.2222,
  // -7.4074, 6.1728, 0), T_m = 0.3 s for S_L = 0.70 m, T_S = 0.6 s, H_m = 0.05 m.
  const Eigen::Vector4d a(-0.35, 0, 5.833333333, -6.481481481);
  EXPECT_LT((gait_.swingX().coefficients() - a).cwiseAbs().maxCoeff(), 1e-8);
  Eigen::VectorXd b(6);
  b << 0, 0, 2.222222222, -7.407407407, 6.172839506, 0;
  EXPECT_LT((gait_.swingY().coefficients() - b).cwiseAbs().maxCoeff(), 1e-8);
  EXPECT_NEAR(gait_.apexTime(), 0.3, 1e-12);
}

TEST_F(PolynomialGaitTest, BoundaryConditionsHoldToMachinePrecision) {
  const double ts = params_.ssp_duration, td = params_.dsp_duration, l = params_.step_length;
  const auto& xa = gait_.swingX();
  const auto& ya = gait_.swingY();
  const double tm = gait_.apexTime();
  EXPECT_NEAR(ya(0), 0, 1e-12);                     // (3.2)
  EXPECT_NEAR(ya(ts), 0, 1e-12);                    // (3.3)
  EXPECT_NEAR(xa(tm), params_.apex_x, 1e-12);       // (3.4)
  EXPECT_NEAR(ya(tm), params_.apex_height, 1e-12);  // (3.5)
  EXPECT_NEAR(ya(tm, 1), 0, 1e-12);                 // (3.6)
  EXPECT_NEAR(xa(0), -l, 1e-12);                    // (3.7)
  EXPECT_NEAR(xa(ts), l, 1e-12);                    // (3.8)
  EXPECT_NEAR(xa(0, 1), 0, 1e-12);                  // (3.9)
  EXPECT_NEAR(ya(0, 1), 0, 1e-12);                  // (3.10)
  EXPECT_NEAR(xa(ts, 1), 0, 1e-12);                 // (3.11)
  EXPECT_NEAR(ya(ts, 1), 0, 1e-12);                 // (3.12)
  const auto& xs = gait_.hipXSsp();
  const auto& xd = gait_.hipXDsp();
  EXPECT_NEAR(xs(0), -params_.hip_start, 1e-12);            // (3.16)
  EXPECT_NEAR(xd(td), l - params_.hip_start, 1e-12);        // (3.17)
  EXPECT_NEAR(xs(0, 1), plan_.velocity_start, 1e-12);       // (3.18)
  EXPECT_NEAR(xd(td, 1), plan_.velocity_start, 1e-12);      // (3.19)
  EXPECT_NEAR(xs(ts), plan_.dsp_start, 1e-12);              // (3.20)
  EXPECT_NEAR(xd(0), plan_.dsp_start, 1e-12);               // (3.21)
  EXPECT_NEAR(xs(ts, 1), plan_.velocity_touchdown, 1e-12);  // (3.22)
  EXPECT_NEAR(xd(0, 1), plan_.velocity_touchdown, 1e-12);   // (3.23)
  for (double t : {0.0, 0.2, 0.6, 0.65, 0.7}) {
    const Phase ph = t < ts ? Phase::kSsp : Phase::kDsp;
    EXPECT_NEAR(gait_.hip(t, ph).pos(1), params_.hip_height, 1e-12);  // (3.14), (3.15)
  }
}

TEST_F(PolynomialGaitTest, InverseKinematicsReproducesTable41) {
  // docs/derivations.md#the-initial-state: hip (-0.15, 0.59), swing tip (-0.36, 0).
  gaits::PointMotion hip{{-0.15, 0.59}, {}, {}};
  gaits::PointMotion tip{{-0.36 + 0.15, -0.59}, {}, {}};
  const auto stance =
      gaits::legInverseKinematics(0.332, 0.302, hip, gaits::KneeDirection::kForward);
  const auto swing = gaits::legInverseKinematics(0.302, 0.332, tip, gaits::KneeDirection::kForward);
  EXPECT_NEAR(stance.theta(0) / kDeg, 1.18, 0.01);
  EXPECT_NEAR(stance.theta(1) / kDeg, -31.29, 0.01);
  EXPECT_NEAR(dynamics::wrapAngle(swing.theta(0), std::numbers::pi) / kDeg, 190.19, 0.01);
  EXPECT_NEAR(dynamics::wrapAngle(swing.theta(1), std::numbers::pi) / kDeg, 208.14, 0.01);
}

TEST_F(PolynomialGaitTest, RatesAndAccelerationsAreExactDerivativesOfTheAngles) {
  // Richardson-extrapolated central differences (error O(h^4)) of the IK angles and rates.
  auto derivative = [&](double t, Phase ph, bool of_rates) {
    auto central = [&](double h) {
      const auto kp = gait_.kinematics(t + h, ph);
      const auto km = gait_.kinematics(t - h, ph);
      return VecD(((of_rates ? kp.dtheta : kp.theta) - (of_rates ? km.dtheta : km.theta)) /
                  (2 * h));
    };
    return VecD((4 * central(5e-4) - central(1e-3)) / 3);
  };
  for (double t : {0.05, 0.3, 0.55, 0.62, 0.68}) {
    const Phase ph = t < params_.ssp_duration ? Phase::kSsp : Phase::kDsp;
    const auto k = gait_.kinematics(t, ph);
    EXPECT_LT((derivative(t, ph, false) - k.dtheta).norm(), 1e-7 * (1 + k.dtheta.norm()));
    EXPECT_LT((derivative(t, ph, true) - k.ddtheta).norm(), 1e-7 * (1 + k.ddtheta.norm()));
    // The tips follow the planned paths.
    EXPECT_LT((dynamics::swingTip(model_, k.theta) - gait_.swingTip(t, ph).pos).norm(), 1e-12);
    EXPECT_LT((dynamics::hip(model_, k.theta) - gait_.hip(t, ph).pos).norm(), 1e-12);
  }
}

TEST_F(PolynomialGaitTest, ContinuousAtTouchdownAndPeriodicAfterRelabelling) {
  const double ts = params_.ssp_duration;
  const auto end_ssp = gait_.kinematics(ts, Phase::kSsp);
  const auto start_dsp = gait_.kinematics(ts, Phase::kDsp);
  EXPECT_LT((end_ssp.theta - start_dsp.theta).norm(), 1e-12);
  EXPECT_LT((end_ssp.dtheta - start_dsp.dtheta).norm(), 1e-12);
  const auto start = gait_.kinematics(0, Phase::kSsp);
  const auto end = gait_.kinematics(params_.duration(), Phase::kDsp);
  EXPECT_LT((dynamics::relabelAngles(model_, end.theta) - start.theta).norm(), 1e-12);
  EXPECT_LT((dynamics::relabelRates(end.dtheta) - start.dtheta).norm(), 1e-12);
}

TEST_F(PolynomialGaitTest, TouchdownTipVelocityIsZeroSoTheImpactVanishes) {
  const auto k = gait_.kinematics(params_.ssp_duration, Phase::kSsp);
  const Vec2d v = dynamics::pointVelocity(model_.tipWeights(), k.theta, k.dtheta);
  EXPECT_LT(v.norm(), 1e-12);
  const auto traj = gaits::buildTrajectory(gait_, model_, 1000);
  EXPECT_LT(gaits::touchdownVelocityJump(traj, model_), 1e-10);
  EXPECT_LT(gaits::impactEnergyLoss(traj, model_), 1e-12);
}

TEST_F(PolynomialGaitTest, UnreachableHipHeightIsAClearError) {
  auto plan = plan_;
  plan.height = 0.70;  // legs are 0.634 m long
  const gaits::PolynomialGait gait(model_, params_, plan);
  try {
    gait.kinematics(0.1, Phase::kSsp);
    FAIL() << "expected a reachability error";
  } catch (const std::domain_error& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("mu2004 at t = 0.1000 s (SSP): leg cannot reach"), std::string::npos) << msg;
    EXPECT_NE(msg.find("outside the open range (0.0300, 0.6340) m"), std::string::npos) << msg;
  }
}

// The hip-plan search asks only whether the legs reach (gaits/polynomial/hip_plan_search.cpp); its
// cheap answer must be the one the inverse kinematics would give, reachable or not.
TEST_F(PolynomialGaitTest, ReachCheckAgreesWithInverseKinematics) {
  int unreachable = 0;
  for (const double hip_height : {0.40, 0.55, 0.62, 0.63, 0.70}) {
    auto plan = plan_;
    plan.height = hip_height;  // legs are 0.634 m long: the higher hips overreach
    const gaits::PolynomialGait gait(model_, params_, plan);
    for (int k = 0; k <= 70; ++k) {
      const double t = params_.duration() * k / 70;
      const Phase phase = t <= params_.ssp_duration ? Phase::kSsp : Phase::kDsp;
      bool solved = true;
      try {
        gait.kinematics(t, phase);
      } catch (const std::domain_error&) {
        solved = false;
      }
      EXPECT_EQ(gait.reachable(t, phase), solved) << "hip height " << hip_height << ", t " << t;
      unreachable += solved ? 0 : 1;
    }
  }
  EXPECT_GT(unreachable, 20);  // both answers were exercised
}

// y_a of (3.10)-(3.12) stays on or above the ground exactly while the apex lies within
// kApexReach step lengths of mid-swing: at the bound its least height is 0, a little beyond it
// the tip passes below the ground, and the gait file refuses such an apex.
TEST_F(PolynomialGaitTest, TheSwingTipStaysAboveTheGroundForEveryApexTheGaitFileAccepts) {
  const auto lowest = [&](double apex_x) {
    gaits::GaitParams p = params_;
    p.apex_x = apex_x;
    const gaits::PolynomialGait gait(model_, p, plan_);
    double y = 1;
    for (int k = 0; k <= 2000; ++k)
      y = std::min(y, gait.swingTip(p.ssp_duration * k / 2000, Phase::kSsp).pos(1));
    return y;
  };
  const double reach = gaits::kApexReach * params_.step_length;
  for (const double x : {-reach, -0.5 * reach, 0.0, reach}) EXPECT_GE(lowest(x), -1e-12) << x;
  EXPECT_LT(lowest(1.05 * reach), -1e-5);
  EXPECT_LT(lowest(-1.05 * reach), -1e-5);
  const std::string file = std::string(GAITOPT_SOURCE_DIR) + "/configs/gaits/mu2004.yaml";
  EXPECT_NO_THROW(gaits::loadGait(file, config::parseOverrides({"swing_apex.x=0.1"})));
  EXPECT_THROW(gaits::loadGait(file, config::parseOverrides({"swing_apex.x=0.11"})),
               config::ConfigError);
}

TEST(LegReach, AgreesWithTheInverseKinematicsAtTheEdgesOfTheWorkspace) {
  const double l_a = 0.332, l_b = 0.302;  // Mu's thigh and shank: reach (0.030, 0.634) m
  const gaits::PointMotion base;
  for (const double dist : {0.0299, 0.0301, 0.3, 0.6339, 0.6341})
    for (const double angle : {0.0, 0.7, 1.5707963, 1.5707963267948966, 2.5, 3.14159}) {
      gaits::PointMotion r = base;
      r.pos = dist * Eigen::Vector2d(std::sin(angle), -std::cos(angle));
      bool solved = true;
      try {
        gaits::legInverseKinematics(l_a, l_b, r, gaits::KneeDirection::kForward);
      } catch (const std::domain_error&) {
        solved = false;
      }
      EXPECT_EQ(gaits::legCanReach(l_a, l_b, r.pos), solved) << dist << " m at " << angle;
    }
  EXPECT_FALSE(gaits::legCanReach(l_a, l_b, Eigen::Vector2d(0.5, 0.0)));  // horizontal
  EXPECT_TRUE(gaits::legCanReach(l_a, l_b, Eigen::Vector2d(0.0, -0.5)));
}

TEST(PolynomialGaitRobots, KneelessRobotIsRejected) {
  const auto model = loadNamed("compass_gait");
  EXPECT_THROW(gaits::PolynomialGait(model, muParams(), {}), std::invalid_argument);
}

}  // namespace
}  // namespace gaitopt::test
