/// @file dsp_coordinates.cpp
/// The double support collocated in theta against Mu's reduced coordinates
/// (constraints.dsp_reduced_coordinates, ocp/problem/dsp_chart.hpp), on each five-link problem with
/// a double support: solve time (median of `repeats` in this process), iterations, cost, and on the
/// 1 kHz export the DSP tip's drift, foot B's centre of pressure and the friction ratio; the drift
/// at the collocation points themselves beside it. Meshes: the config's equal segments, and a DSP
/// mesh finer after the impact. Usage: dsp_coordinates [repeats]   (prints a markdown table)
#include <cstdlib>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "bench/ocp_bench_common.hpp"
#include "gaits/export/export_checks.hpp"
#include "gaits/export/metrics.hpp"
#include "ocp/guess/initial_guess.hpp"
#include "ocp/problem/gait_problem.hpp"
#include "ocp/problem/ocp_config.hpp"

namespace {

using namespace gaitopt;

struct Variant {
  const char* name;
  bool reduced;
  std::vector<double> mesh;  ///< of the DSP; empty: the config's equal segments
};

/// The DSP's first segment shortened to 10 ms: the forces change fastest after the impact.
const std::vector<double> kGraded = {0, 0.1, 0.28, 0.46, 0.64, 0.82, 1.0};

const std::vector<Variant> kVariants = {{"theta, equal segments", false, {}},
                                        {"reduced, equal segments", true, {}},
                                        {"theta, finer after impact", false, kGraded},
                                        {"reduced, finer after impact", true, kGraded}};

void printRow(const std::string& config, const Variant& v, int repeats) {
  ocp::OcpConfig c = ocp::loadOcpConfig(std::string(GAITOPT_SOURCE_DIR) + "/configs/ocp/" + config);
  c.dsp_reduced_coordinates = v.reduced;
  c.phases.back().mesh = v.mesh;
  const dynamics::Model model = ocp::problemModel(c);
  const ocp::GaitProblem p = ocp::buildGaitProblem(model, c, ocp::polynomialGuess(model, c));
  const bench::TimedSolve s = bench::solveRepeated(p.nlp, c.solver, repeats, 2.0);
  const Eigen::VectorXd& x = s.last.x;
  const gaits::Trajectory dense = ocp::reconstructDense(p, model, x, 1000.0);
  const double friction = gaits::maxFrictionRatio(dense);
  fmt::print("| {} | {} | {} | {} | {:.6g} | {:.3f} | {:.1e} | {:.1e} | {:+.4f} | {:.3f} |\n",
             config, v.name, s.last.success ? "yes" : "no", s.last.iterations, s.last.cost, s.wall,
             gaits::maxDspTipDrift(ocp::reconstruct(p, model, x), model),
             gaits::maxDspTipDrift(dense, model), gaits::minFootCopMargin(dense, model), friction);
}

}  // namespace

int main(int argc, char** argv) {
  const int repeats = argc > 1 ? std::atoi(argv[1]) : 3;
  fmt::print(
      "| config | DSP | converged | iterations | cost | wall s | tip drift at the points m | "
      "tip drift at 1 kHz m | least foot-B CoP margin at 1 kHz m | friction ratio at 1 kHz |\n"
      "|---|---|---|---:|---:|---:|---:|---:|---:|---:|\n");
  for (const char* config : {"mu2004_walk.yaml", "mu2004_walk_robust.yaml", "mu2004_walk_cot.yaml"})
    for (const Variant& v : kVariants) printRow(config, v, repeats);
  fmt::print("\nMedians of {} solves per row in one process (one for a solve over 2 s).\n",
             repeats);
}
