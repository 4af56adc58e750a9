#pragma once
// The momentum laws of an impact whose only impulse acts at the swing tip E (a single impact,
// Mu 2.32-2.36; with friction, Hurmuzlu et al. 2001 sec. 3.3): angular momentum about E is
// conserved, and the impulse is the change of linear momentum. The base (the old stance tip B)
// moves at base_velocity after the impact.
#include <cmath>

#include <gtest/gtest.h>

#include "dynamics/energy.hpp"
#include "dynamics/kinematics.hpp"

namespace gaitopt::test {

inline void expectImpulseAtSwingTipOnly(const dynamics::Model& m, const VecD& theta,
                                        const VecD& dtheta_minus, const VecD& dtheta_plus,
                                        const Vec2d& base_velocity, const Vec2d& impulse,
                                        double tolerance) {
  const Vec2d e = dynamics::swingTip(m, theta);
  const double before = dynamics::angularMomentum<double>(m, theta, dtheta_minus, Vec2d::Zero(), e);
  const double after = dynamics::angularMomentum<double>(m, theta, dtheta_plus, base_velocity, e);
  EXPECT_NEAR(after, before, tolerance * (1 + std::abs(before)));
  const Vec2d dp = dynamics::linearMomentum<double>(m, theta, dtheta_plus, base_velocity) -
                   dynamics::linearMomentum<double>(m, theta, dtheta_minus);
  EXPECT_LT((impulse - dp).norm(), tolerance * (1 + dp.norm()));
}

}  // namespace gaitopt::test
