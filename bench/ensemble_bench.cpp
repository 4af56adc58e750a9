/// @file ensemble_bench.cpp
/// What the ensemble costs in solve time: configs/ocp/mu2004_walk_ensemble.yaml solved whole
/// (its continuation of the margins and the strike included) with K = 1, 3 and 5 models: the
/// nominal alone, the shipped mass variants 0.9 and 1.1, and those plus 0.95 and 1.05. Each row
/// is the median wall time of `repeats` solves from the polynomial guess, with its ratio to
/// K = 1 and the optimum's cost; each takes the config's whole path, its retries and halved steps
/// included. A solve longer than a minute is timed once.
/// Usage: ensemble_bench [repeats]
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "bench/ocp_bench_common.hpp"
#include "ocp/guess/initial_guess.hpp"
#include "ocp/problem/gait_problem.hpp"
#include "ocp/shape/shape_config.hpp"
#include "ocp/solve/gait_solve.hpp"

namespace {

using namespace gaitopt;

/// The mass scales of the variants beside the nominal.
const std::vector<std::vector<double>> kEnsembles = {{}, {0.9, 1.1}, {0.9, 0.95, 1.05, 1.1}};

/// The config with the ensemble's variants, solved whole from the polynomial guess.
bench::TimedSolve solveRepeated(const std::string& path, const std::vector<double>& mass_scales,
                                int repeats) {
  ocp::OcpConfig config = ocp::loadOcpConfig(path);
  config.solver.progress = false;
  config.shape.variants.clear();
  for (const double scale : mass_scales) config.shape.variants.push_back({scale});
  const dynamics::Model model = ocp::problemModel(config);
  const gaits::Trajectory guess = ocp::initialGuess(model, config);
  return bench::timeRepeated([&] { return ocp::solveGait(model, config, guess).result; }, repeats,
                             60.0);
}

}  // namespace

int main(int argc, char** argv) {
  const int repeats = argc > 1 ? std::max(1, std::atoi(argv[1])) : 3;
  const std::string path =
      std::string(GAITOPT_SOURCE_DIR) + "/configs/ocp/mu2004_walk_ensemble.yaml";
  fmt::print(
      "mu2004_walk_ensemble, whole solve with its continuation, {} solves per row, "
      "medians\n\n",
      repeats);
  fmt::print(
      "| models K | status | iterations | cost J | wall s | wall / K=1 | solves |\n"
      "|---:|---|---:|---:|---:|---:|---:|\n");
  double single = 0;
  for (const std::vector<double>& mass_scales : kEnsembles) {
    const bench::TimedSolve t = solveRepeated(path, mass_scales, repeats);
    if (single == 0) single = t.wall;
    const ocp::SolveResult& r = t.last;
    fmt::print("| {} | {} | {} | {:.2f} | {:.2f} | {:.2f} | {} |\n", mass_scales.size() + 1,
               r.status, r.iterations, r.cost, t.wall, t.wall / single, t.solves);
    std::fflush(stdout);
  }
  return 0;
}
