/// @file ground_bench.cpp
/// Speed against accuracy of the three grounds: the five-link robot with a 0.30 m heel
/// (tests/apps/mu2004_five_link_long_heel.yaml, where the polynomial gait's ZMP fits the foot; on
/// the shipped 5 cm heel it walks on a saturated ankle and falls at step 1) tracks the
/// polynomial gait (configs/gaits/mu2004.yaml) for 10 steps with computed torque on rigid,
/// impedance (configs/grounds/impedance.yaml, and a 10x stiffer floor) and LCP ground over a
/// range of time steps. Accuracy against a tightly converged rigid reference (RK4 h = 5e-5 s,
/// events to 1e-12 s): the path, as the largest difference of hip height at the same hip x (a
/// compliant floor sinks and lands earlier, which a comparison at equal times would mistake for
/// a large error), and the timing, as the difference of the walk's end time. Cost: the wall time
/// of the walk, median of `repeats` runs. A walk that fails (diverged, slipped, fell)
/// is a row with its failure: that is where the method stops working.
/// Prints CSV: ground,variant,time_step,steps,failure,hip_deviation_m,timing_s,wall_s
/// Usage: ground_bench [repeats]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "dynamics/kinematics.hpp"
#include "dynamics/robot_files/robot_config.hpp"
#include "ocp/guess/initial_guess.hpp"
#include "sim/contact/ground_config.hpp"
#include "sim/walk/walk.hpp"

namespace {

using namespace gaitopt;

constexpr int kSteps = 10;

struct HipPath {
  std::vector<double> t;
  std::vector<Vec2d> hip;
};

sim::WalkLog recordHip(const dynamics::Model& plant, HipPath& path) {
  return [&plant, &path](const sim::WalkSample& s) {
    if (!path.t.empty() && s.t <= path.t.back()) return;  // keep times strictly increasing
    path.t.push_back(s.t);
    path.hip.push_back(dynamics::hip<double>(plant, s.theta) + Vec2d(s.stance_x, s.stance_y));
  };
}

/// max |y_hip(x) - y_hip,ref(x)| at the reference's samples inside both paths, the path's hip
/// height interpolated linearly in x (the hip moves forward throughout a walk).
double pathDeviation(const HipPath& ref, const HipPath& path) {
  double worst = 0;
  std::size_t j = 1;
  for (std::size_t i = 0; i < ref.t.size(); ++i) {
    const double x = ref.hip[i](0);
    if (path.t.size() < 2 || x < path.hip.front()(0) || x > path.hip.back()(0)) continue;
    while (j + 1 < path.hip.size() && path.hip[j](0) < x) ++j;
    const double dx = path.hip[j](0) - path.hip[j - 1](0);
    const double a = dx > 0 ? (x - path.hip[j - 1](0)) / dx : 0;
    const double y = (1 - a) * path.hip[j - 1](1) + a * path.hip[j](1);
    worst = std::max(worst, std::abs(y - ref.hip[i](1)));
  }
  return worst;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

struct Run {
  sim::WalkResult walk;
  HipPath path;
  double wall;
};

Run walkOn(const dynamics::Model& model, const sim::TrackingController& controller,
           const sim::Reference& ref, const sim::GroundModel& ground, int repeats) {
  Run run;
  std::vector<double> wall;
  for (int k = 0; k < repeats; ++k) {
    run.path = {};
    const auto start = std::chrono::steady_clock::now();
    run.walk =
        sim::walk(model, controller, ref, ground, {kSteps, {}, {}}, recordHip(model, run.path));
    wall.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  }
  run.wall = median(wall);
  return run;
}

sim::GroundModel withStep(sim::GroundModel g, double h) {
  if (auto* rigid = g.getIf<sim::RigidGround>()) rigid->integrator.step = h;
  if (auto* compliant = g.getIf<sim::CompliantGround>()) compliant->time_step = h;
  if (auto* lcp = g.getIf<sim::LcpGround>()) lcp->time_step = h;
  return g;
}

}  // namespace

int main(int argc, char** argv) {
  const int repeats = argc > 1 ? std::max(1, std::atoi(argv[1])) : 3;
  const std::string root = GAITOPT_SOURCE_DIR;
  const auto config = ocp::loadOcpConfig(root + "/configs/ocp/mu2004_walk.yaml");
  const auto model = dynamics::loadRobot(root + "/tests/apps/mu2004_five_link_long_heel.yaml");
  const sim::Reference ref(ocp::polynomialGuess(model, config), model);
  const sim::TrackingController controller(model,
                                           std::make_unique<sim::PdLaw>(sim::TrackingGains{}));

  sim::RigidGround tight;
  tight.integrator = {5e-5, 1e-12};
  const Run reference = walkOn(model, controller, ref, tight, 1);
  if (reference.walk.steps_completed != kSteps) {
    fmt::print(stderr, "the rigid reference failed: {}\n", reference.walk.failure);
    return 1;
  }
  const auto impedance = sim::loadGround(root + "/configs/grounds/impedance.yaml");
  auto stiff = *impedance.getIf<sim::CompliantGround>();
  stiff.contact.stiffness *= 10;
  stiff.contact.damping *= 10;
  struct Case {
    std::string ground, variant;
    sim::GroundModel model;
    std::vector<double> steps;
  };
  const std::vector<Case> cases{
      {"rigid",
       "RK4 + events",
       sim::loadGround(root + "/configs/grounds/rigid.yaml"),
       {1e-2, 5e-3, 2e-3, 1e-3, 5e-4, 2e-4}},
      {"impedance", "shipped floor", impedance, {1e-3, 5e-4, 2e-4, 1e-4, 5e-5, 2e-5}},
      {"impedance", "10x stiffer", stiff, {5e-4, 2e-4, 1e-4, 5e-5, 2e-5}},
      {"lcp",
       "Stewart-Trinkle",
       sim::loadGround(root + "/configs/grounds/lcp.yaml"),
       {1e-2, 5e-3, 2e-3, 1e-3, 5e-4, 2e-4}},
  };
  fmt::print("ground,variant,time_step,steps,failure,hip_deviation_m,timing_s,wall_s\n");
  for (const auto& c : cases)
    for (double h : c.steps) {
      const Run run = walkOn(model, controller, ref, withStep(c.model, h), repeats);
      const double timing =
          run.walk.fell ? NAN : std::abs(run.path.t.back() - reference.path.t.back());
      fmt::print("{},{},{:g},{},\"{}\",{:.3e},{:.3e},{:.4f}\n", c.ground, c.variant, h,
                 run.walk.steps_completed, run.walk.failure,
                 pathDeviation(reference.path, run.path), timing, run.wall);
      std::fflush(stdout);
    }
  return 0;
}
