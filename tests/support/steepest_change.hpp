#pragma once
/// @file steepest_change.hpp
/// How fast a knot quantity changes along a trajectory: the largest |x(t_{i+1}) - x(t_i)| /
/// (t_{i+1} - t_i) over consecutive knots of one phase, entry by entry. The rate bounds of the OCP
/// (jerk_limit.hpp on the accelerations, torque_rate_limit.hpp on the torques) are checked with it.
#include <algorithm>

#include <Eigen/Core>

#include "gaits/trajectory/trajectory.hpp"

namespace gaitopt::test {

inline double steepestChange(const gaits::Trajectory& t, Eigen::VectorXd gaits::Knot::*member) {
  const auto& k = t.knots();
  double steepest = 0;
  for (size_t i = 1; i < k.size(); ++i)
    if (k[i - 1].phase == k[i].phase && k[i].t > k[i - 1].t)
      steepest = std::max(steepest, (k[i].*member - k[i - 1].*member).cwiseAbs().maxCoeff() /
                                        (k[i].t - k[i - 1].t));
  return steepest;
}

}  // namespace gaitopt::test
