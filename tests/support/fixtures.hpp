#pragma once
/// Shared test helpers: robot files, reproducible random states.
#include <numbers>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "dynamics/kinematics.hpp"
#include "dynamics/model.hpp"
#include "dynamics/robot_files/robot_config.hpp"

namespace gaitopt::test {

inline std::string robotPath(const std::string& name) {
  return std::string(GAITOPT_SOURCE_DIR) + "/configs/robots/" + name + ".yaml";
}

inline dynamics::Model loadNamed(const std::string& name) {
  return dynamics::loadRobot(robotPath(name));
}

/// Every shipped robot: the same code must serve them all.
inline const std::vector<std::string>& allRobots() {
  static const std::vector<std::string> names{"mu2004_five_link", "rabbit", "three_link",
                                              "compass_gait"};
  return names;
}

/// Uniform random vector in [lo, hi]^n from a seeded engine.
inline VecD randomVec(std::mt19937& rng, int n, double lo, double hi) {
  std::uniform_real_distribution<double> dist(lo, hi);
  VecD v(n);
  for (int i = 0; i < n; ++i) v(i) = dist(rng);
  return v;
}

/// A random walking-like posture: stance leg and torso near upright, swing leg near pi.
inline VecD randomPosture(std::mt19937& rng, const dynamics::Model& model) {
  VecD theta = randomVec(rng, model.nLinks(), -0.6, 0.6);
  for (int i = model.nLinks() - model.legLinks(); i < model.nLinks(); ++i)
    theta(i) += std::numbers::pi;
  return theta;
}

/// A pre-impact state: a random posture whose swing tip moves down (and either way along the
/// ground).
inline std::pair<VecD, VecD> preImpact(const dynamics::Model& m, std::mt19937& rng) {
  const VecD theta = randomPosture(rng, m);
  VecD dtheta = randomVec(rng, m.nLinks(), -2, 2);
  if ((dynamics::pointJacobian(m.tipWeights(), theta) * dtheta)(1) > 0) dtheta = -dtheta;
  return {theta, dtheta};
}

/// Relative error ||a - b|| / max(||b||, floor).
template <class A, class B>
double relErr(const A& a, const B& b, double floor = 1e-12) {
  return (a - b).norm() / std::max(b.norm(), floor);
}

}  // namespace gaitopt::test
