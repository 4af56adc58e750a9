// Velocity-level time stepping with the Stewart-Trinkle LCP: a point mass (x, y) on level
// ground against closed forms, a bar on two contacts (lever rule), and Coulomb's law on random
// systems.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>

#include "sim/contact/lcp_contact_step.hpp"

namespace gaitopt::test {
namespace {

using sim::ContactRows;
using sim::LcpStepResult;
using sim::LemkeStatus;

constexpr double kBlockMass = 2.0;  // [kg]
constexpr double kG = 9.81;         // [m/s^2]
constexpr double kH = 1e-3;         // [s]

/// Point mass (x, y) under gravity; ground y = 0 with normal +y and tangent +x.
struct PointMass {
  Eigen::Vector2d q = Eigen::Vector2d::Zero();
  Eigen::Vector2d v = Eigen::Vector2d::Zero();

  /// One step with friction mu; positions by semi-implicit Euler.
  LcpStepResult step(double mu) {
    const ContactRows ground{Eigen::RowVector2d(0, 1), Eigen::RowVector2d(1, 0), q(1), mu};
    const LcpStepResult r =
        sim::lcpContactStep(kBlockMass * Eigen::Matrix2d::Identity(),
                            Eigen::Vector2d(0, -kBlockMass * kG), v, kH, {ground});
    EXPECT_EQ(r.status, LemkeStatus::kSolved);
    v = r.velocity;
    q += kH * v;
    return r;
  }
};

TEST(LcpContactStep, RestingMassStaysAtRest) {
  PointMass p;
  for (int k = 0; k < 1000; ++k) {
    const LcpStepResult r = p.step(0.5);
    ASSERT_NEAR(r.normal_impulse(0), kBlockMass * kG * kH, 1e-12) << "step " << k;
    ASSERT_NEAR(r.tangential_impulse(0), 0, 1e-12);
  }
  EXPECT_LT(p.q.lpNorm<Eigen::Infinity>(), 1e-12);
  EXPECT_LT(p.v.lpNorm<Eigen::Infinity>(), 1e-12);
}

TEST(LcpContactStep, ImpactIsInelasticAndSticksWithLargeFriction) {
  // At the ground with v = (1, -2): p_n = m (2 + g h) stops the normal motion; stopping the slip
  // needs |p_t| = m * 1 < mu p_n.
  PointMass p;
  p.v = Eigen::Vector2d(1, -2);
  const LcpStepResult r = p.step(1.0);
  EXPECT_NEAR(r.normal_impulse(0), kBlockMass * (2 + kG * kH), 1e-12);
  EXPECT_NEAR(r.tangential_impulse(0), -kBlockMass * 1.0, 1e-12);
  EXPECT_LT(r.velocity.lpNorm<Eigen::Infinity>(), 1e-12);
}

TEST(LcpContactStep, ImpactSlidesWithSmallFriction) {
  // Same impact, mu = 0.1: the friction impulse saturates at mu p_n.
  PointMass p;
  p.v = Eigen::Vector2d(1, -2);
  const LcpStepResult r = p.step(0.1);
  const double pn = kBlockMass * (2 + kG * kH);
  EXPECT_NEAR(r.normal_impulse(0), pn, 1e-12);
  EXPECT_NEAR(r.tangential_impulse(0), -0.1 * pn, 1e-12);
  EXPECT_NEAR(r.velocity(0), 1 - 0.1 * pn / kBlockMass, 1e-12);
  EXPECT_NEAR(r.velocity(1), 0, 1e-12);
}

TEST(LcpContactStep, DroppedMassLandsWithoutPenetrationAndSticks) {
  PointMass p;
  p.q = Eigen::Vector2d(0, 0.05);
  p.v = Eigen::Vector2d(1, 0);
  int first_contact = -1;
  for (int k = 0; k < 400; ++k) {
    const LcpStepResult r = p.step(2.0);
    ASSERT_GE(p.q(1), -1e-12) << "step " << k;
    if (first_contact < 0 && r.normal_impulse(0) > 0) first_contact = k;
    // The gap term lands the mass exactly on the ground at the end of the first contact step;
    // the next one removes the remaining normal and (mu = 2) tangential velocity.
    if (first_contact >= 0 && k >= first_contact + 1) {
      ASSERT_LT(p.v.lpNorm<Eigen::Infinity>(), 1e-12) << "step " << k;
    }
  }
  ASSERT_GT(first_contact, 0);
  EXPECT_NEAR(p.q(1), 0, 1e-12);
}

TEST(LcpContactStep, SlidingMassDeceleratesAtMuG) {
  // On the ground, v = (2, 0), mu = 0.3: each step removes mu g h of speed until it stops, so
  // v_x(k) = max(0, v0 - mu g h k) exactly, and the distance is v0^2 / (2 mu g) + O(h).
  const double mu = 0.3;
  const double v0 = 2.0;
  PointMass p;
  p.v = Eigen::Vector2d(v0, 0);
  for (int k = 1; k <= 1000; ++k) {
    p.step(mu);
    ASSERT_NEAR(p.v(0), std::max(0.0, v0 - mu * kG * kH * k), 1e-12) << "step " << k;
    ASSERT_NEAR(p.v(1), 0, 1e-12);
  }
  EXPECT_NEAR(p.q(0), v0 * v0 / (2 * mu * kG), v0 * kH);
}

TEST(LcpContactStep, SeparatedOrSeparatingContactCarriesNoImpulse) {
  PointMass approaching;  // 1 cm above, 1 m/s down: not reached within h
  approaching.q = Eigen::Vector2d(0, 0.01);
  approaching.v = Eigen::Vector2d(0.5, -1);
  EXPECT_EQ(approaching.step(1.0).normal_impulse(0), 0);
  EXPECT_NEAR(approaching.v(1), -1 - kG * kH, 1e-12);
  PointMass leaving;  // on the ground, moving up faster than gravity can stop in h
  leaving.v = Eigen::Vector2d(0.5, 1);
  const LcpStepResult r = leaving.step(1.0);
  EXPECT_EQ(r.normal_impulse(0), 0);
  EXPECT_EQ(r.tangential_impulse(0), 0);
  EXPECT_NEAR(leaving.v(0), 0.5, 1e-15);
}

TEST(LcpContactStep, BarOnTwoContactsSharesTheLoadByTheLeverRule) {
  // Bar (x, y, theta) about its CoM, flat, contacts at r1 = -0.3 m and r2 = +0.5 m along it:
  // n_i = (0, 1, r_i), t_i = (1, 0, 0). Statics: p1 + p2 = m g h, r1 p1 + r2 p2 = 0.
  const double m = 3.0;
  const double r1 = -0.3;
  const double r2 = 0.5;
  const Eigen::Matrix3d mass = Eigen::Vector3d(m, m, 0.2).asDiagonal();
  const std::vector<ContactRows> contacts{
      {Eigen::RowVector3d(0, 1, r1), Eigen::RowVector3d(1, 0, 0), 0.0, 0.8},
      {Eigen::RowVector3d(0, 1, r2), Eigen::RowVector3d(1, 0, 0), 0.0, 0.8}};
  const LcpStepResult r = sim::lcpContactStep(mass, Eigen::Vector3d(0, -m * kG, 0),
                                              Eigen::Vector3d::Zero(), kH, contacts);
  ASSERT_EQ(r.status, LemkeStatus::kSolved);
  EXPECT_NEAR(r.normal_impulse(0), m * kG * kH * r2 / (r2 - r1), 1e-12);
  EXPECT_NEAR(r.normal_impulse(1), m * kG * kH * -r1 / (r2 - r1), 1e-12);
  EXPECT_NEAR(r.tangential_impulse.sum(), 0, 1e-12);  // friction pairs may be internal
  EXPECT_LT(r.velocity.lpNorm<Eigen::Infinity>(), 1e-12);
}

TEST(LcpContactStep, RandomSystemsObeySignoriniAndCoulomb) {
  std::mt19937 rng(7);
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> unit(0, 1);
  int slipping = 0;
  for (int trial = 0; trial < 200; ++trial) {
    const int nq = 3 + trial % 4;
    const int nc = 1 + trial % 3;
    Eigen::MatrixXd a(nq, nq);
    for (auto& x : a.reshaped()) x = normal(rng);
    const Eigen::MatrixXd mass = a * a.transpose() + 0.1 * Eigen::MatrixXd::Identity(nq, nq);
    Eigen::VectorXd force(nq), v(nq);
    for (int i = 0; i < nq; ++i) force(i) = 10 * normal(rng), v(i) = normal(rng);
    std::vector<ContactRows> contacts;
    for (int i = 0; i < nc; ++i) {
      ContactRows c{Eigen::RowVectorXd(nq), Eigen::RowVectorXd(nq), 0.0, unit(rng)};
      for (int j = 0; j < nq; ++j) c.normal(j) = normal(rng), c.tangent(j) = normal(rng);
      contacts.push_back(c);
    }
    const LcpStepResult r = sim::lcpContactStep(mass, force, v, kH, contacts);
    ASSERT_EQ(r.status, LemkeStatus::kSolved) << "trial " << trial;
    // Momentum balance recomputed independently of the solver's M^-1 G.
    Eigen::VectorXd impulse = kH * force;
    for (int i = 0; i < nc; ++i) {
      impulse += contacts[i].normal.transpose() * r.normal_impulse(i) +
                 contacts[i].tangent.transpose() * r.tangential_impulse(i);
    }
    EXPECT_LT((mass * (r.velocity - v) - impulse).norm(), 1e-9 * (1 + impulse.norm()));
    for (int i = 0; i < nc; ++i) {
      const double vn = contacts[i].normal.dot(r.velocity);
      const double vt = contacts[i].tangent.dot(r.velocity);
      const double pn = r.normal_impulse(i);
      const double pt = r.tangential_impulse(i);
      EXPECT_GE(pn, 0);
      EXPECT_GE(vn, -1e-9);
      EXPECT_LT(std::abs(pn * vn), 1e-9);
      EXPECT_LE(std::abs(pt), contacts[i].friction * pn + 1e-9);
      if (std::abs(vt) > 1e-7) {  // slipping: maximal dissipation, friction opposes the slip
        EXPECT_NEAR(pt, -std::copysign(contacts[i].friction * pn, vt), 1e-9);
        ++slipping;
      }
    }
  }
  EXPECT_GT(slipping, 20);  // the trials exercise sliding, not only sticking and lift-off
}

TEST(LcpContactStep, RejectsBadInput) {
  const Eigen::Matrix2d mass = Eigen::Matrix2d::Identity();
  const Eigen::Vector2d f(0, -1);
  const Eigen::Vector2d v(0, 0);
  const ContactRows ok{Eigen::RowVector2d(0, 1), Eigen::RowVector2d(1, 0), 0.0, 0.5};
  EXPECT_NO_THROW(sim::lcpContactStep(mass, f, v, kH, {ok}));
  EXPECT_THROW(sim::lcpContactStep(mass, f, v, 0.0, {ok}), std::invalid_argument);
  EXPECT_THROW(sim::lcpContactStep(mass, f, Eigen::Vector3d::Zero(), kH, {ok}),
               std::invalid_argument);
  ContactRows bad = ok;
  bad.friction = -0.1;
  EXPECT_THROW(sim::lcpContactStep(mass, f, v, kH, {bad}), std::invalid_argument);
  bad = ok;
  bad.tangent = Eigen::RowVector3d(1, 0, 0);
  EXPECT_THROW(sim::lcpContactStep(mass, f, v, kH, {bad}), std::invalid_argument);
  bad = ok;
  bad.gap = NAN;
  EXPECT_THROW(sim::lcpContactStep(mass, f, v, kH, {bad}), std::invalid_argument);
  EXPECT_THROW(sim::lcpContactStep(-mass, f, v, kH, {ok}), std::invalid_argument);
}

}  // namespace
}  // namespace gaitopt::test
