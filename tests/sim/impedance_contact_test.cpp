// Compliant point contact: a point mass (x, y) on the Hunt-Crossley ground, integrated here by
// fixed-step RK4, against energy conservation, the Hunt-Crossley restitution law, Coulomb
// sliding, and the force laws evaluated directly.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "sim/contact/impedance_contact.hpp"

namespace gaitopt::test {
namespace {

using sim::ImpedanceGround;

constexpr double kPadMass = 1.0;  // [kg]

/// Point mass with state (x, y, xdot, ydot) on the ground y = 0, and the tangential anchor.
struct Body {
  Eigen::Vector4d s = Eigen::Vector4d::Zero();
  double anchor = 0;
};

sim::ContactPointMotion motion(const Eigen::Vector4d& s) {
  return {-s(1), -s(3), s(0), s(2)};
}

Eigen::Vector4d derivative(const ImpedanceGround& ground, double g, const Eigen::Vector4d& s,
                           double anchor) {
  const sim::ImpedanceContactForce f = sim::impedanceContactForce(ground, motion(s), anchor);
  return {s(2), s(3), f.tangential / kPadMass, f.normal / kPadMass - g};
}

/// Classical RK4 with the anchor of the last accepted step in every stage, then the anchor
/// update from the accepted state (the protocol impedance_contact.hpp documents).
sim::ImpedanceContactForce rk4Step(const ImpedanceGround& ground, double g, double dt, Body& b) {
  const Eigen::Vector4d k1 = derivative(ground, g, b.s, b.anchor);
  const Eigen::Vector4d k2 = derivative(ground, g, b.s + dt / 2 * k1, b.anchor);
  const Eigen::Vector4d k3 = derivative(ground, g, b.s + dt / 2 * k2, b.anchor);
  const Eigen::Vector4d k4 = derivative(ground, g, b.s + dt * k3, b.anchor);
  b.s += dt / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
  const sim::ImpedanceContactForce f = sim::impedanceContactForce(ground, motion(b.s), b.anchor);
  b.anchor = f.anchor;
  return f;
}

ImpedanceGround hertzGround(double damping) {
  return {.stiffness = 1e5,
          .damping = damping,
          .exponent = 1.5,
          .tangential_stiffness = 1e5,
          .tangential_damping = 2 * std::sqrt(1e5 * kPadMass),
          .friction = 0.4};
}

/// Mechanical energy including the elastic energy k delta^(n+1) / (n+1) stored in the ground.
double energy(const ImpedanceGround& ground, double g, const Eigen::Vector4d& s) {
  const double delta = std::max(0.0, -s(1));
  return kPadMass * (0.5 * s.tail<2>().squaredNorm() + g * s(1)) +
         ground.stiffness * std::pow(delta, ground.exponent + 1) / (ground.exponent + 1);
}

TEST(ImpedanceContact, UndampedDropBouncesBackToItsHeight) {
  const ImpedanceGround ground = hertzGround(0.0);
  const double g = 9.81;
  const double h0 = 0.1;
  Body b;
  b.s(1) = h0;
  const double e0 = energy(ground, g, b.s);
  double max_energy_error = 0;
  bool touched = false;
  while (!(touched && b.s(1) > 0 && b.s(3) > 0)) {  // until back in flight, going up
    rk4Step(ground, g, 1e-5, b);
    touched = touched || b.s(1) < 0;
    max_energy_error = std::max(max_energy_error, std::abs(energy(ground, g, b.s) - e0));
  }
  const double apex = b.s(1) + b.s(3) * b.s(3) / (2 * g);  // exact in free flight
  EXPECT_NEAR(apex, h0, 1e-8);
  EXPECT_LT(max_energy_error / e0, 1e-8);
}

/// Coefficient of restitution of a normal impact at `speed` without gravity, from RK4 with a
/// step of 1/4000 of the Hertz contact duration.
double restitution(const ImpedanceGround& ground, double speed) {
  const double n = ground.exponent;
  const double max_delta =
      std::pow((n + 1) * kPadMass * speed * speed / (2 * ground.stiffness), 1 / (n + 1));
  const double dt = 3 * max_delta / speed / 4000;
  Body b;
  b.s(3) = -speed;
  do {
    rk4Step(ground, 0.0, dt, b);
  } while (b.s(1) < 0);
  return b.s(3) / speed;
}

/// Exact restitution of the Hunt-Crossley law F = k delta^n (1 + b delta_dot), b = c / k. With
/// s = delta^(n+1) / (n+1), m u du / (1 + b u) = -k ds (u = delta_dot) no longer contains n:
/// compression from v to rest and restitution from rest to e v store and release the same
/// s_max, so P(v) = Q(e v) with P(x) = x / b - ln(1 + b x) / b^2 = int_0^x y / (1 + b y) dy and
/// Q(x) = -x / b - ln(1 - b x) / b^2 = int_0^x y / (1 - b y) dy. Solved for e by bisection.
double exactRestitution(double b, double speed) {
  const double p = speed / b - std::log1p(b * speed) / (b * b);
  const auto q = [b](double x) { return -x / b - std::log1p(-b * x) / (b * b); };
  double lo = 0;
  double hi = 1;
  for (int i = 0; i < 100; ++i) {
    const double mid = (lo + hi) / 2;
    (q(mid * speed) < p ? lo : hi) = mid;
  }
  return lo;
}

TEST(ImpedanceContact, RestitutionFollowsHuntCrossley) {
  // c = (3/2) alpha k: e falls with the impact speed, e ~ 1 - alpha v for alpha v << 1, and e
  // depends on alpha v only (not on the exponent, see exactRestitution).
  const double alpha = 0.2;  // [s/m]
  for (const double exponent : {1.0, 1.5}) {
    ImpedanceGround ground = hertzGround(0.0);
    ground.exponent = exponent;
    ground.damping = 1.5 * alpha * ground.stiffness;
    double previous = 1;
    for (const double v : {0.01, 0.03, 0.1, 0.3, 1.0}) {
      const double e = restitution(ground, v);
      EXPECT_NEAR(e, exactRestitution(1.5 * alpha, v), 1e-7) << "n = " << exponent << ", v = " << v;
      EXPECT_LT(e, previous) << "n = " << exponent << ", v = " << v;
      previous = e;
    }
    // Small-speed limit: (1 - e) / (alpha v) = 1 - O(alpha v).
    const double e_small = restitution(ground, 0.01);
    EXPECT_NEAR((1 - e_small) / (alpha * 0.01), 1.0, 3e-3);
  }
}

TEST(ImpedanceContact, SlidingBlockDeceleratesAtMuG) {
  // Resting at the static penetration (k delta0^n = m g), pushed at v0 = 1 m/s.
  const ImpedanceGround ground = hertzGround(500.0);
  const double g = 9.81;
  const double v0 = 1.0;
  const double mu = ground.friction;
  Body b;
  b.s(1) = -std::pow(kPadMass * g / ground.stiffness, 1 / ground.exponent);
  b.s(2) = v0;
  const double dt = 1e-5;
  double v_early = 0;
  for (int k = 1; k <= 40000; ++k) {
    const sim::ImpedanceContactForce f = rk4Step(ground, g, dt, b);
    if (k == 5000) v_early = b.s(2);
    if (k == 20000) {  // 0.05 s to 0.2 s: sliding throughout (it stops at v0 / (mu g) = 0.255 s)
      EXPECT_TRUE(f.sliding);
      EXPECT_NEAR((v_early - b.s(2)) / (15000 * dt), mu * g, 1e-9 * mu * g);
      EXPECT_NEAR(b.s(2), v0 - mu * g * k * dt, 1e-9);
    }
  }
  EXPECT_LT(std::abs(b.s(2)), 1e-6);  // stuck after 0.4 s
  EXPECT_NEAR(b.s(0), v0 * v0 / (2 * mu * g),
              mu * kPadMass * g / ground.tangential_stiffness + 1e-5);
}

TEST(ImpedanceContact, NormalForceNeverPulls) {
  const ImpedanceGround ground = hertzGround(1.5 * 0.2 * 1e5);
  const double release = -ground.stiffness / ground.damping;  // below this rate k + c rate < 0
  for (const double delta : {-1e-3, 0.0, 1e-5, 1e-3, 1e-2}) {
    for (const double rate : {-100.0, 10 * release, release, 0.5 * release, -0.01, 0.0, 1.0}) {
      const double fn = sim::huntCrossleyNormalForce(ground, delta, rate);
      EXPECT_GE(fn, 0) << delta << " " << rate;
      if (delta <= 0 || rate <= release) {
        EXPECT_EQ(fn, 0) << delta << " " << rate;
      } else {
        EXPECT_NEAR(fn, std::pow(delta, 1.5) * (ground.stiffness + ground.damping * rate),
                    1e-12 * (1 + fn));
      }
    }
  }
}

TEST(ImpedanceContact, TangentialForceSticksThenSlidesAndMovesTheAnchor) {
  const ImpedanceGround ground = hertzGround(0.0);
  const double delta = 1e-3;
  const double fn = ground.stiffness * std::pow(delta, 1.5);
  // Stick: 10 um from the anchor at rest, spring force 1 N < mu Fn.
  const auto stick = sim::impedanceContactForce(ground, {delta, 0, 1e-5, 0}, 0.0);
  EXPECT_FALSE(stick.sliding);
  EXPECT_NEAR(stick.tangential, -1.0, 1e-12);
  EXPECT_EQ(stick.anchor, 0.0);
  // Slide: moving at 1 m/s, damper alone exceeds mu Fn; force -mu Fn, spring made consistent.
  const auto slide = sim::impedanceContactForce(ground, {delta, 0, 0.2, 1.0}, 0.2);
  EXPECT_TRUE(slide.sliding);
  EXPECT_NEAR(slide.tangential, -ground.friction * fn, 1e-12);
  EXPECT_NEAR(-ground.tangential_stiffness * (0.2 - slide.anchor), slide.tangential, 1e-9);
  // Normal force dropped below the stored spring force (10 N > mu Fn) while the point creeps
  // back toward the anchor: the force keeps the spring's direction instead of flipping to
  // oppose the creep, and the anchor is pulled along.
  const auto unload = sim::impedanceContactForce(ground, {delta, 0, 1e-4, -1e-3}, 0.0);
  EXPECT_TRUE(unload.sliding);
  EXPECT_NEAR(unload.tangential, -ground.friction * fn, 1e-12);
  EXPECT_NEAR(unload.anchor, 1e-4 - ground.friction * fn / ground.tangential_stiffness, 1e-15);
  // Out of contact the anchor follows the point.
  const auto air = sim::impedanceContactForce(ground, {-1e-3, 0, 0.7, 3.0}, 0.0);
  EXPECT_EQ(air.normal, 0);
  EXPECT_EQ(air.tangential, 0);
  EXPECT_EQ(air.anchor, 0.7);
}

// Addi & Rodic's pad (60): the force at a given squeeze is their stiffening law k delta (1 + 0.1
// tan^3(pi delta / (2 t_p))), damped only while compressing; a body dropped on it from any height
// this test tries stops inside the pad's thickness, where the linear spring alone would let it
// through.
TEST(ImpedanceContact, ThePadStiffensTowardsItsThicknessAndDampsOnlyWhileCompressed) {
  ImpedanceGround pad = hertzGround(0.0);
  pad.exponent = 1.0;
  pad.damping = 1.5 * 3.0 * pad.stiffness;
  pad.pad_thickness = 0.005;
  for (const double delta : {0.001, 0.0025, 0.004}) {
    const double law = pad.stiffness * delta *
                       (1 + 0.1 * std::pow(std::tan(std::numbers::pi * delta / 0.01), 3));
    EXPECT_NEAR(sim::huntCrossleyNormalForce(pad, delta, -0.3), law, 1e-9 * law);  // restoring
    EXPECT_NEAR(sim::huntCrossleyNormalForce(pad, delta, 0.3), law * (1 + 4.5 * 0.3),
                1e-9 * law);  // compressing
  }
  ImpedanceGround spring = pad;
  spring.pad_thickness = 0;
  spring.damping = 0;
  for (const double v : {2.0, 3.0}) {  // [m/s]: the linear spring alone sinks 6.3 and 9.5 mm
    double deepest_pad = 0, deepest_spring = 0;
    for (auto [ground, deepest] : {std::pair{&pad, &deepest_pad}, {&spring, &deepest_spring}}) {
      Body b;
      b.s << 0, 0, 0, -v;
      for (int k = 0; k < 20000 && b.s(3) <= 0; ++k) {
        rk4Step(*ground, 9.81, 1e-6, b);
        *deepest = std::max(*deepest, -b.s(1));
      }
    }
    EXPECT_LT(deepest_pad, pad.pad_thickness) << v;
    EXPECT_GT(deepest_spring, pad.pad_thickness) << v;
  }
}

TEST(ImpedanceContact, BadParametersNameTheParameter) {
  EXPECT_NO_THROW(sim::validateImpedanceGround(hertzGround(10.0)));
  const std::vector<std::pair<std::string, void (*)(ImpedanceGround&)>> cases{
      {"stiffness", [](ImpedanceGround& p) { p.stiffness = 0; }},
      {"damping", [](ImpedanceGround& p) { p.damping = -1; }},
      {"exponent", [](ImpedanceGround& p) { p.exponent = 0.5; }},
      {"tangential_stiffness", [](ImpedanceGround& p) { p.tangential_stiffness = NAN; }},
      {"tangential_damping", [](ImpedanceGround& p) { p.tangential_damping = -2; }},
      {"friction", [](ImpedanceGround& p) { p.friction = INFINITY; }}};
  for (const auto& [name, spoil] : cases) {
    ImpedanceGround ground = hertzGround(10.0);
    spoil(ground);
    try {
      sim::validateImpedanceGround(ground);
      ADD_FAILURE() << name << " accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("ImpedanceGround." + name + ":"), std::string::npos)
          << e.what();
    }
  }
}

}  // namespace
}  // namespace gaitopt::test
