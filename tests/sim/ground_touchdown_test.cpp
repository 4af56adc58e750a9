// "The three ground models agree on a slow, soft touchdown": the five-link robot at the
// touchdown posture of the polynomial gait, standing on B, brings its swing tip E down at
// 0.05 m/s. Rigid ground: Mu's double impact map (dynamics/impact/impact.hpp), then the pinned
// double support (2.11). Compliant and LCP grounds: the free-base steppers of the walks. All under
// the same double-support controller; after a settling time the link rates must agree.
#include <gtest/gtest.h>

#include <cmath>

#include <fmt/format.h>
#include <Eigen/QR>

#include "dynamics/dsp_dynamics.hpp"
#include "dynamics/floating_base_dynamics.hpp"
#include "dynamics/ground.hpp"
#include "dynamics/impact/impact.hpp"
#include "dynamics/kinematics.hpp"
#include "dynamics/ssp_dynamics.hpp"
#include "five_link_gait.hpp"
#include "sim/contact/compliant_walk.hpp"
#include "sim/contact/ground_config.hpp"
#include "sim/contact/lcp_walk.hpp"

namespace gaitopt::sim {
namespace {

using gaits::Phase;
constexpr double kApproachSpeed = 0.05;  // [m/s]
constexpr double kSettle = 0.1;          // [s] after touchdown

class SoftTouchdown : public ::testing::Test {
 protected:
  SoftTouchdown() {
    const gaits::Knot& td = ref_.at(Phase::kSsp, ref_.touchdownTime());
    theta_ = td.theta;
    // The gait sets E down at zero speed; add the least-norm rates that move it down.
    const Eigen::MatrixXd jac = dynamics::pointJacobian<double>(plant_.tipWeights(), theta_);
    dtheta_ =
        VecD(td.dtheta) +
        VecD(jac.completeOrthogonalDecomposition().solve(Eigen::Vector2d(0, -kApproachSpeed)));
  }

  VecD dspTorque(double t, const VecD& theta, const VecD& dtheta) const {
    return controller_.torque(Phase::kDsp, theta, dtheta, ref_.at(Phase::kDsp, start_ + t), {});
  }
  TorqueFeedback feedback(double t) const {
    const int n = plant_.nLinks();
    return [this, t, n](double dt, const Eigen::VectorXd& q, const Eigen::VectorXd& v) {
      return dspTorque(t + dt, q.tail(n), v.tail(n));
    };
  }

  /// Rigid: impact map, then the pinned DSP under the controller to kSettle.
  VecD rigid() const {
    // Mu's (2.31a) finds a pulling impulse at B, but the single impact would lift B by less than
    // 1 cm/s, which its weight prevents: the rigid walk takes that as a double impact too
    // (hybrid_walk.cpp, kGentleLiftoff).
    EXPECT_LT(dynamics::singleImpact(plant_, theta_, dtheta_).trailing_velocity(1), 0.01);
    const auto impact = dynamics::doubleImpact(plant_, theta_, dtheta_);
    jump_ = (VecD(impact.dtheta_plus) - dtheta_).cwiseAbs().maxCoeff();
    const int n = plant_.nLinks();
    Eigen::VectorXd x(2 * n);
    x << theta_, impact.dtheta_plus;
    const Rhs f = [&](double t, const Eigen::VectorXd& s) {
      const VecD th = s.head(n), dth = s.tail(n);
      Eigen::VectorXd xdot(2 * n);
      xdot << dth, dynamics::dspForwardDynamics(plant_, th, dth, dspTorque(t, th, dth)).ddtheta;
      return xdot;
    };
    const double h = 1e-4;
    for (double t = 0; t < kSettle - h / 2; t += h) x = rk4Step(f, t, x, h);
    return x.tail(n);
  }

  /// A free-base ground from the same pre-impact state, B carrying its single-support load.
  template <class Step>
  FreeBaseState settle(const FreeBaseState& start, double h, const Step& step) const {
    FreeBaseState s = start;
    for (double t = 0; t < kSettle - h / 2; t += h) {
      const ContactStep c = step(s, feedback(t));
      EXPECT_EQ(c.failure, "");
      s = c.next;
    }
    return s;
  }

  /// The ground force at B just before touchdown (single support, same controller).
  Vec2d stanceLoad() const {
    const VecD tau = controller_.torque(Phase::kSsp, theta_, dtheta_,
                                        ref_.at(Phase::kSsp, ref_.touchdownTime()), {});
    const VecD dd = dynamics::sspForwardDynamics(plant_, theta_, dtheta_, tau);
    return dynamics::stanceForce<double>(plant_, theta_, dtheta_, dd, Vec2d::Zero());
  }

  const dynamics::Model& plant_ = test::fiveLinkRobot();
  const Reference ref_{test::polynomialGait()};
  const TrackingController controller_ = test::computedTorque();
  const double start_ = ref_.touchdownTime();
  VecD theta_, dtheta_;
  mutable double jump_ = 0;  ///< largest rate jump of the rigid impact [rad/s]
};

TEST_F(SoftTouchdown, ThreeGroundsAgreeOnTheRatesAfterSettling) {
  const std::string dir = std::string(GAITOPT_SOURCE_DIR) + "/configs/grounds/";
  const auto compliant = *loadGround(dir + "impedance.yaml").getIf<CompliantGround>();
  const auto lcp = *loadGround(dir + "lcp.yaml").getIf<LcpGround>();
  const int n = plant_.nLinks();
  const VecD rigid_rates = rigid();

  // Compliant: the robot sunk so that B carries its single-support load (1 mm) and its
  // tangential spring the friction force; E, at B's height, starts as deep. Turning the swing
  // leg to put E exactly at the surface would be a posture error the controller answers at its
  // 20 rad/s bandwidth, a larger disturbance than the one it removes.
  const Vec2d load = stanceLoad();
  const double sink =
      std::pow(load(1) / compliant.contact.stiffness, 1 / compliant.contact.exponent);
  FreeBaseState soft = freeBaseStart(plant_, theta_, dtheta_, 0, -sink);
  soft.anchor(0) = load(0) / compliant.contact.tangential_stiffness;
  const FreeBaseState soft_end = settle(
      soft, compliant.time_step,
      [&](const auto& s, const auto& f) { return compliantContactStep(plant_, compliant, s, f); });
  const FreeBaseState hard_end =
      settle(freeBaseStart(plant_, theta_, dtheta_), lcp.time_step,
             [&](const auto& s, const auto& f) { return lcpGroundStep(plant_, lcp, s, f); });
  const double soft_error = (VecD(soft_end.v.tail(n)) - rigid_rates).cwiseAbs().maxCoeff();
  const double hard_error = (VecD(hard_end.v.tail(n)) - rigid_rates).cwiseAbs().maxCoeff();
  RecordProperty("impact_rate_jump", fmt::format("{:.3e}", jump_));
  RecordProperty("compliant_rate_error", fmt::format("{:.3e}", soft_error));
  RecordProperty("lcp_rate_error", fmt::format("{:.3e}", hard_error));
  // The impact changes the rates by 0.35 rad/s. Tolerance 1e-2 rad/s (3% of that): what is
  // left after 0.1 s of the compliant contact's lightly damped vibration (measured 3.4e-3) and
  // the first-order error of 1 ms time stepping with torques held over the step (4.3e-3).
  EXPECT_GT(jump_, 0.3);
  EXPECT_LT(soft_error, 1e-2);
  EXPECT_LT(hard_error, 1e-2);
  // Both tips at rest again, as the rigid map leaves them.
  EXPECT_LT(soft_end.v.head<2>().norm(), 1e-3);
  EXPECT_LT(dynamics::floatingSwingTipVelocity(plant_, soft_end.q, soft_end.v).norm(), 1e-3);
  EXPECT_LT(hard_end.v.head<2>().norm(), 1e-3);
  EXPECT_LT(dynamics::floatingSwingTipVelocity(plant_, hard_end.q, hard_end.v).norm(), 1e-3);
}

}  // namespace
}  // namespace gaitopt::sim
