/// @file ocp_bench.cpp
/// Solve times of the RABBIT benchmark (Kelly 2017; configs/ocp/rabbit_kelly2017.yaml) from the
/// polynomial guess: Hermite-Simpson with 6, 15 and 25 segments, exact Hessian versus Ipopt's
/// limited-memory approximation. Each case is solved `repeats` times; the table gives medians
/// and the ratio of each median wall time to the exact-Hessian one of the same mesh.
/// Usage: ocp_bench [repeats]
#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "dynamics/robot_config.hpp"
#include "gaits/polynomial_gait.hpp"
#include "ocp/gait_problem.hpp"
#include "ocp/ipopt_adapter.hpp"

namespace {

using namespace gaitopt;

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

struct Row {
  int segments;
  std::string hessian;
  ocp::SolveResult last;
  double wall, callbacks;
};

Row run(const ocp::OcpConfig& base, const dynamics::Model& model, const gaits::Trajectory& guess,
        int segments, const std::string& hessian, int repeats) {
  ocp::OcpConfig c = base;
  c.phases.front().segments = segments;
  c.solver.hessian = hessian;
  const ocp::GaitProblem p = ocp::buildGaitProblem(model, c, guess);
  std::vector<double> wall, callbacks;
  ocp::SolveResult r;
  for (int k = 0; k < repeats; ++k) {
    r = ocp::solveWithIpopt(p.nlp, c.solver);
    wall.push_back(r.wall_time_s);
    callbacks.push_back(r.callback_time_s);
  }
  return {segments, hessian, r, median(wall), median(callbacks)};
}

}  // namespace

int main(int argc, char** argv) {
  const int repeats = argc > 1 ? std::max(1, std::atoi(argv[1])) : 7;
  const auto config =
      ocp::loadOcpConfig(std::string(GAITOPT_SOURCE_DIR) + "/configs/ocp/rabbit_kelly2017.yaml");
  const auto model = dynamics::loadRobot(config.robot_path);
  const auto gp = gaits::loadGait(config.guess_gait_path);
  const gaits::PolynomialGait gait(
      model, gp, {*gp.hip_velocity_start, *gp.hip_velocity_touchdown, *gp.hip_dsp_start});
  const gaits::Trajectory guess = gaits::buildTrajectory(gait, model, 1000);

  fmt::print("RABBIT (Kelly 2017), Hermite-Simpson, tol {:g}, {} solves per row, medians\n\n",
             config.solver.tolerance, repeats);
  fmt::print(
      "| segments | Hessian | status | iterations | cost J | wall s | callbacks s | "
      "callback share | wall / exact |\n|---:|---|---|---:|---:|---:|---:|---:|---:|\n");
  for (int segments : {6, 15, 25}) {
    double exact_wall = 0;
    for (const std::string hessian : {"exact", "limited-memory"}) {
      const Row r = run(config, model, guess, segments, hessian, repeats);
      if (hessian == "exact") exact_wall = r.wall;
      fmt::print("| {} | {} | {} | {} | {:.4f} | {:.4f} | {:.4f} | {:.0f} % | {:.2f} |\n", segments,
                 hessian, r.last.status, r.last.iterations, r.last.cost, r.wall, r.callbacks,
                 100 * r.callbacks / r.wall, r.wall / exact_wall);
    }
  }
  return 0;
}
