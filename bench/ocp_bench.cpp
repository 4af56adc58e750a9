/// @file ocp_bench.cpp
/// Solve times from the config's initial guess, exact derivatives versus Ipopt's limited-memory
/// Hessian, with our Jacobian or with Ipopt's finite differences of the constraints: the
/// default five-link problem (configs/ocp/mu2004_walk.yaml: SSP 30 + DSP 6 Hermite-Simpson
/// segments, double impact) and the RABBIT benchmark of Kelly 2017
/// (configs/ocp/rabbit_kelly2017.yaml) at 6, 15 and 25 segments, and the straight-leg robots
/// from their straight-leg guess (configs/ocp/compass_gait_walk.yaml, three_link_walk.yaml and
/// the passive slope walk compass_gait_passive.yaml, 25 segments each). Each case is solved
/// `repeats` times; the table gives medians and the ratio of each median wall time to the
/// exact-Hessian one of the same problem. Usage: ocp_bench [repeats]
#include <algorithm>
#include <cstdio>
#include <string>

#include <fmt/format.h>

#include "bench/ocp_bench_common.hpp"
#include "ocp/guess/initial_guess.hpp"
#include "ocp/problem/gait_problem.hpp"
#include "ocp/solve/ipopt_adapter.hpp"

namespace {

using namespace gaitopt;

/// One table row per derivative mode for `config` with the SSP cut into `segments`.
void benchmark(const std::string& label, ocp::OcpConfig config, int segments, int repeats) {
  const auto model = ocp::problemModel(config);
  const gaits::Trajectory guess = ocp::initialGuess(model, config);
  config.phases.front().segments = segments;
  double exact_wall = 0;
  for (const auto& [hessian, jacobian] : bench::kDerivativeModes) {
    config.solver.hessian = hessian;
    config.solver.jacobian = jacobian;
    const bench::TimedSolve r = bench::solveRepeated(
        ocp::buildGaitProblem(model, config, guess).nlp, config.solver, repeats);
    if (exact_wall == 0) exact_wall = r.wall;
    fmt::print("| {} | {} | {} | {} | {} | {} | {:.4f} | {:.4f} | {:.4f} | {:.0f} % | {:.2f} |\n",
               label, segments, hessian, jacobian == "exact" ? "exact" : "finite differences",
               r.last.status, r.last.iterations, r.last.cost, r.wall, r.callbacks,
               100 * r.callbacks / r.wall, r.wall / exact_wall);
  }
}

}  // namespace

int main(int argc, char** argv) {
  const int repeats = argc > 1 ? std::max(1, std::atoi(argv[1])) : 7;
  const std::string dir = std::string(GAITOPT_SOURCE_DIR) + "/configs/ocp/";
  const auto five_link = ocp::loadOcpConfig(dir + "mu2004_walk.yaml");
  const auto rabbit = ocp::loadOcpConfig(dir + "rabbit_kelly2017.yaml");
  fmt::print("Hermite-Simpson, Ipopt tol {:g}, {} solves per row, medians\n\n",
             five_link.solver.tolerance, repeats);
  fmt::print(
      "| problem | SSP segments | Hessian | Jacobian | status | iterations | cost J | wall s | "
      "callbacks s | callback share | wall / exact |\n"
      "|---|---:|---|---|---|---:|---:|---:|---:|---:|---:|\n");
  benchmark("five-link SSP+DSP (mu2004_walk)", five_link, five_link.phases.front().segments,
            repeats);
  for (int segments : {6, 15, 25}) benchmark("RABBIT (Kelly 2017)", rabbit, segments, repeats);
  for (const char* name : {"compass_gait_walk", "three_link_walk", "compass_gait_passive"}) {
    const auto config = ocp::loadOcpConfig(dir + name + ".yaml");
    benchmark(name, config, config.phases.front().segments, repeats);
  }
  return 0;
}
