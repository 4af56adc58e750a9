#pragma once
/// Field-by-field equality of knots and of whole steps, for tests of readers and writers that
/// must give back exactly what they were given (no tolerance: the formats print round-trip
/// digits).
#include <gtest/gtest.h>

#include <cstddef>

#include "gaits/trajectory/trajectory.hpp"

namespace gaitopt::test {

inline void expectSameKnot(const gaits::Knot& x, const gaits::Knot& y, std::size_t k = 0) {
  EXPECT_EQ(x.t, y.t) << "knot " << k;
  EXPECT_EQ(x.phase, y.phase) << "knot " << k;
  EXPECT_EQ(x.theta, y.theta) << "knot " << k;
  EXPECT_EQ(x.dtheta, y.dtheta) << "knot " << k;
  EXPECT_EQ(x.ddtheta, y.ddtheta) << "knot " << k;
  EXPECT_EQ(x.tau, y.tau) << "knot " << k;
  EXPECT_EQ(x.force_stance, y.force_stance) << "knot " << k;
  EXPECT_EQ(x.force_swing, y.force_swing) << "knot " << k;
}

inline void expectSameKnots(const gaits::Trajectory& a, const gaits::Trajectory& b) {
  ASSERT_EQ(a.knots().size(), b.knots().size());
  for (std::size_t k = 0; k < a.knots().size(); ++k) expectSameKnot(a.knots()[k], b.knots()[k], k);
}

}  // namespace gaitopt::test
