// Double support: pinned tips, contact forces, momentum balance, and the reduced model (2.21),
// against the independent floating-base KKT formulation.
#include <numbers>

#include <gtest/gtest.h>

#include "dynamics/dsp_dynamics.hpp"
#include "dynamics/ground.hpp"
#include "support/fixtures.hpp"
#include "support/floating_base.hpp"

namespace gaitopt::test {
namespace {

using dynamics::Model;

/// A DSP posture: random stance leg and torso; the swing leg solved so that E is on the ground
/// (two-link IK for knees, or the one-link leg for single-segment legs), with rates projected
/// onto the null space of J so both tips are at rest.
struct DspState {
  VecD theta, dtheta;
  double step_length;
};

DspState makeDspState(const Model& m, std::mt19937& rng) {
  const int n = m.nLinks();
  const int k = m.legLinks();
  for (;;) {
    VecD theta = randomPosture(rng, m);
    const Vec2d hip = dynamics::hip(m, theta);
    if (k == 1) {
      // Straight legs: the swing leg reaches the ground iff it mirrors the stance leg.
      theta(n - 1) = std::numbers::pi - theta(0);
    } else {
      // Place E ahead of the hip and solve the swing thigh/shank angles (two-link IK).
      const double l1 = m.link(n - 2).length;
      const double l2 = m.link(n - 1).length;
      const double step = hip(0) + std::uniform_real_distribution<double>(0.05, 0.3)(rng);
      const Vec2d to_tip(step - hip(0), -hip(1));
      const double dist = to_tip.norm();
      if (dist >= l1 + l2 - 1e-3 || dist <= std::abs(l1 - l2) + 1e-3) continue;
      const double base = std::atan2(to_tip(0), to_tip(1));
      const double inner = std::acos((l1 * l1 + dist * dist - l2 * l2) / (2 * l1 * dist));
      theta(n - 2) = base + inner;
      const Vec2d knee = hip + l1 * Vec2d(std::sin(theta(n - 2)), std::cos(theta(n - 2)));
      const Vec2d rest = Vec2d(step, 0) - knee;
      theta(n - 1) = std::atan2(rest(0), rest(1));
    }
    const Vec2d tip = dynamics::swingTip(m, theta);
    if (std::abs(tip(1)) > 1e-12 || tip(0) < 0.02) continue;
    const Mat2Xd jac = dynamics::pointJacobian(m.tipWeights(), theta);
    const Eigen::MatrixXd proj =
        Eigen::MatrixXd::Identity(n, n) - jac.transpose() * (jac * jac.transpose()).inverse() * jac;
    const VecD dtheta = proj * Eigen::VectorXd(randomVec(rng, n, -2, 2));
    return {theta, dtheta, tip(0)};
  }
}

class DspTest : public ::testing::TestWithParam<std::string> {
 protected:
  Model model_ = loadNamed(GetParam());
  std::mt19937 rng_{11};
};

TEST_P(DspTest, AccelerationsKeepBothTipsPinned) {
  for (int trial = 0; trial < 50; ++trial) {
    const DspState s = makeDspState(model_, rng_);
    const VecD tau = randomVec(rng_, model_.nLinks(), -50, 50);
    const auto sol = dynamics::dspForwardDynamics(model_, s.theta, s.dtheta, tau);
    const Vec2d tip_acc =
        dynamics::pointAcceleration(model_.tipWeights(), s.theta, s.dtheta, sol.ddtheta);
    EXPECT_LT(tip_acc.norm(), 1e-10);
    EXPECT_LT(dynamics::dspConstraint(model_, s.theta, s.step_length).norm(), 1e-12);
    EXPECT_LT(
        dynamics::dspResidual(model_, s.theta, s.dtheta, sol.ddtheta, tau, sol.force_swing).norm(),
        1e-9);
  }
}

TEST_P(DspTest, TipForcesMatchFloatingBaseAndBalanceMomentum) {
  const int n = model_.nLinks();
  for (int trial = 0; trial < 50; ++trial) {
    const DspState s = makeDspState(model_, rng_);
    const VecD tau = randomVec(rng_, n, -50, 50);
    const auto sol = dynamics::dspForwardDynamics(model_, s.theta, s.dtheta, tau);

    // Floating base, both tips held by contact forces: q = (x_b, y_b, theta).
    const FloatingBase fb = floatingBase(model_, s.theta, s.dtheta);
    Eigen::MatrixXd jac(4, n + 2);
    jac << fb.jac_b, fb.jac_e;
    Eigen::Vector4d c;
    c << 0, 0, -fb.jdot_e;
    const auto [qdd, forces] = solveKkt(fb.mass, actuation(model_, tau) - fb.bias, jac, c);
    EXPECT_LT(relErr(sol.ddtheta, VecD(qdd.tail(n)), 1.0), 1e-9);
    EXPECT_LT(relErr(sol.force_swing, Vec2d(forces.tail<2>()), 1.0), 1e-9);

    // Total linear momentum: F_B + F_E - m g e_y = m a_com, with F_B from the floating base.
    const Vec2d f_b = forces.head<2>();
    const Vec2d a_com =
        dynamics::pointAcceleration(model_.totalComWeights(), s.theta, s.dtheta, sol.ddtheta);
    const Vec2d residual =
        f_b + sol.force_swing - model_.totalMass() * (a_com + Vec2d(0, model_.gravity()));
    EXPECT_LT(residual.norm(), 1e-9 * (1 + f_b.norm()));
    // stanceForce() derives F_B from the same balance: it must agree with the floating base.
    EXPECT_LT(relErr(dynamics::stanceForce(model_, s.theta, s.dtheta, sol.ddtheta, sol.force_swing),
                     f_b, 1.0),
              1e-9);
  }
}

TEST_P(DspTest, ReducedModelMatchesKkt) {
  if (model_.nLinks() < 3) {
    // A two-link chain pinned at both tips is rigid: the reduced model must refuse it.
    const DspState s = makeDspState(model_, rng_);
    EXPECT_THROW(dynamics::reducedDspModel(model_, s.theta, s.dtheta), std::invalid_argument);
    return;
  }
  for (int trial = 0; trial < 50; ++trial) {
    const DspState s = makeDspState(model_, rng_);
    const VecD tau = randomVec(rng_, model_.nLinks(), -50, 50);
    const auto sol = dynamics::dspForwardDynamics(model_, s.theta, s.dtheta, tau);
    const auto red = dynamics::reducedDspModel(model_, s.theta, s.dtheta);
    const VecD t_minus_n = dynamics::generalizedTorque(tau) - red.n_vec;
    const VecD pddot = red.b * red.pdot + red.c * t_minus_n;  // (2.21)
    const auto rc = dynamics::reducedCoordinates(model_, s.theta, s.dtheta);
    const VecD pddot_kkt = rc.r * sol.ddtheta + rc.rdot_dth;
    EXPECT_LT(relErr(pddot, pddot_kkt, 1.0), 1e-9);
    const Vec2d lambda = red.lam_p * red.pdot + red.lam_t * t_minus_n;  // (2.20b)
    EXPECT_LT(relErr(lambda, sol.force_swing, 1.0), 1e-9);
  }
}

INSTANTIATE_TEST_SUITE_P(AllRobots, DspTest, ::testing::ValuesIn(allRobots()));

}  // namespace
}  // namespace gaitopt::test
