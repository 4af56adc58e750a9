/// @file ensemble_bench.cpp
/// What the ensemble costs in solve time: configs/ocp/mu2004_walk_ensemble.yaml solved whole
/// (its continuation of the margins and the strike included) with K = 1, 3 and 5 models: the
/// nominal alone, the shipped variants, and those plus a copy halfway between the nominal and each
/// of them (the shipped 0.9 mass and 0.95 lengths, 1.1 mass: 0.95 and 0.975, 1.05). Each row
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

using Variants = std::vector<ocp::VariantConfig>;

/// The variants beside the nominal: none, the shipped ones, and those with a copy halfway to each.
std::vector<Variants> ensembles(const Variants& shipped) {
  Variants halfway = shipped;
  for (const ocp::VariantConfig& v : shipped)
    halfway.push_back({(1 + v.mass_scale) / 2, (1 + v.length_scale) / 2, v.controller_case});
  return {{}, shipped, halfway};
}

/// The config with the ensemble's variants, solved whole from the polynomial guess.
bench::TimedSolve solveRepeated(ocp::OcpConfig config, const Variants& variants, int repeats) {
  config.solver.progress = false;
  config.shape.variants = variants;
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
  const ocp::OcpConfig config = ocp::loadOcpConfig(path);
  double single = 0;
  for (const Variants& variants : ensembles(config.shape.variants)) {
    const bench::TimedSolve t = solveRepeated(config, variants, repeats);
    if (single == 0) single = t.wall;
    const ocp::SolveResult& r = t.last;
    fmt::print("| {} | {} | {} | {:.2f} | {:.2f} | {:.2f} | {} |\n", variants.size() + 1, r.status,
               r.iterations, r.cost, t.wall, t.wall / single, t.solves);
    std::fflush(stdout);
  }
  return 0;
}
