// The jerk-jump bound (ocp/problem/jerk_jump.hpp): where two segments meet, the slopes of the
// export's accelerations on either side differ by at most the bound. Measured on the dense export
// independently of the set's own stencil: at a rate whose samples fall on every node, the
// three-point one-sided differences of the accelerations are the exact end slopes of each
// segment's quadratic. The unbounded default optimum jumps by more, at less cost.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "ocp/problem/gait_problem.hpp"
#include "support/solved_config.hpp"

namespace gaitopt::ocp {
namespace {

constexpr double kJump = 2000;  // rad/s^3
// Samples on every node of the default problem on equal DSP segments: SSP nodes every 20 ms, DSP
// every 1/60 s.
constexpr double kNodeRate = 6000;  // Hz

/// The default problem with its DSP collocated in theta on 6 equal segments, where the export's
/// accelerations are the collocated ones, and the jump bound (0: off), solved from its
/// polynomial guess.
OcpConfig defaultWithJump(double jump) {
  auto c = loadOcpConfig(test::shippedOcpConfig("mu2004_walk"));
  c.dsp_reduced_coordinates = false;
  c.phases.back().first_segment = 0;
  c.jerk_jump_limit = jump;
  return c;
}

/// The largest jump of the export's jerk at a node strictly inside a phase [rad/s^3]: the nodes
/// are every other point of the solution (Hermite-Simpson), found among the dense samples.
double largestJerkJump(const test::SolvedConfig& s) {
  const auto points = reconstruct(s.problem, s.model, s.result.x).knots();
  const auto dense = reconstructDense(s.problem, s.model, s.result.x, kNodeRate).knots();
  const double h = 1 / kNodeRate;
  double worst = 0;
  size_t first = 0;  // the first point of the current phase
  for (size_t p = 0; p < points.size(); ++p) {
    if (points[p].phase != points[first].phase) first = p;
    const bool last = p + 1 == points.size() || points[p + 1].phase != points[p].phase;
    if (p == first || last || (p - first) % 2 != 0) continue;
    const auto at = std::find_if(dense.begin(), dense.end(), [&](const gaits::Knot& k) {
      return k.phase == points[p].phase && std::abs(k.t - points[p].t) < 1e-9;
    });
    EXPECT_NE(at, dense.end()) << "no sample at the node at t = " << points[p].t;
    if (at == dense.end() || at - dense.begin() < 2 || dense.end() - at < 3) continue;
    const VecD left = (3 * at->ddtheta - 4 * (at - 1)->ddtheta + (at - 2)->ddtheta) / (2 * h);
    const VecD right = (-3 * at->ddtheta + 4 * (at + 1)->ddtheta - (at + 2)->ddtheta) / (2 * h);
    worst = std::max(worst, (right - left).cwiseAbs().maxCoeff());
  }
  return worst;
}

TEST(JerkJump, TheExportsJerkJumpsNoMoreThanTheBoundAtEveryNode) {
  const test::SolvedConfig bounded(defaultWithJump(kJump));
  ASSERT_TRUE(bounded.result.success) << bounded.result.status;
  EXPECT_LT(largestJerkJump(bounded), kJump * (1 + 1e-5));

  const test::SolvedConfig free(defaultWithJump(0));
  ASSERT_TRUE(free.result.success) << free.result.status;
  EXPECT_GT(largestJerkJump(free), 2 * kJump);
  EXPECT_GT(bounded.result.cost, free.result.cost);  // the bound is active and costs torque
}

}  // namespace
}  // namespace gaitopt::ocp
