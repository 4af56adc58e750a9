/// @file dsp_coordinates.cpp
/// The double support collocated in theta against Mu's reduced coordinates
/// (constraints.dsp_reduced_coordinates, ocp/problem/dsp_chart.hpp), on each five-link problem with
/// a double support: solve time (median of `repeats` in this process), iterations, cost, and on the
/// 1 kHz export the DSP tip's drift, foot B's centre of pressure and the friction ratio; the drift
/// at the collocation points themselves beside it, and the export's rates and accelerations against
/// the differences of its angles and rates (gaits/export/export_checks.hpp). Meshes: the config's
/// equal segments, a DSP graded from 5 ms after the impact, and the config's 6 segments with the
/// first 12 ms long; then the default problem at 24..36 SSP segments in theta and in reduced
/// coordinates with that 12 ms first segment. Usage: dsp_coordinates [repeats] (prints two
/// markdown tables)
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
  int segments;          ///< of the DSP; 0: the config's
  double first_segment;  ///< PhaseConfig::first_segment; 0: equal segments
};

/// Graded: a 5 ms first DSP segment, each later one at most 1.5 times the one before (the forces
/// change fastest after the impact), 7 segments instead of 6. "12 ms first": the same grading
/// from 12 ms on 6 segments: of the first segments tried between 5 and 15 ms, the shortest that
/// kept the default's 15 iterations at its 30 SSP segments (docs/optimal_gaits.md).
const Variant kTheta{"theta, equal segments", false, 0, 0.0};
const Variant kReduced12{"reduced, 12 ms first", true, 6, 0.12};
const std::vector<Variant> kVariants = {kTheta,
                                        {"reduced, equal segments", true, 0, 0.0},
                                        {"theta, graded", false, 7, 0.05},
                                        {"reduced, graded", true, 7, 0.05},
                                        kReduced12};

/// @param ssp_segments 0: the config's.
void printRow(const std::string& config, const Variant& v, int repeats, int ssp_segments = 0) {
  ocp::OcpConfig c = ocp::loadOcpConfig(std::string(GAITOPT_SOURCE_DIR) + "/configs/ocp/" + config);
  if (ssp_segments > 0) c.phases.front().segments = ssp_segments;
  c.dsp_reduced_coordinates = v.reduced;
  c.phases.back().clearMesh();
  if (v.segments > 0) c.phases.back().segments = v.segments;
  c.phases.back().first_segment = v.first_segment;
  const dynamics::Model model = ocp::problemModel(c);
  const ocp::GaitProblem p = ocp::buildGaitProblem(model, c, ocp::polynomialGuess(model, c));
  const bench::TimedSolve s = bench::solveRepeated(p.nlp, c.solver, repeats, 2.0);
  const Eigen::VectorXd& x = s.last.x;
  const gaits::Trajectory dense = ocp::reconstructDense(p, model, x, 1000.0);
  const double friction = gaits::maxFrictionRatio(dense);
  fmt::print(
      "| {}{} | {} | {} | {} | {:.6g} | {:.3f} | {:.1e} | {:.1e} | {:+.4f} | {:.4f} | {:.2f} "
      "| {:.2f} |\n",
      config, ssp_segments > 0 ? fmt::format(" at {}", ssp_segments) : "", v.name,
      s.last.success ? "yes" : "no", s.last.iterations, s.last.cost, s.wall,
      gaits::maxDspTipDrift(ocp::reconstruct(p, model, x), model),
      gaits::maxDspTipDrift(dense, model), gaits::minFootCopMargin(dense, model), friction,
      100 * gaits::maxRateMismatch(dense), 100 * gaits::maxAccelerationMismatch(dense));
}

void printHeader() {
  fmt::print(
      "| config | DSP | converged | iterations | cost | wall s | tip drift at the points m | "
      "tip drift at 1 kHz m | least foot-B CoP margin at 1 kHz m | friction ratio at 1 kHz | "
      "rate mismatch % of peak | acceleration mismatch % of peak |\n"
      "|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
}

}  // namespace

int main(int argc, char** argv) {
  const int repeats = argc > 1 ? std::atoi(argv[1]) : 3;
  printHeader();
  for (const char* config : {"mu2004_walk.yaml", "mu2004_walk_robust.yaml", "mu2004_walk_cot.yaml"})
    for (const Variant& v : kVariants) printRow(config, v, repeats);
  fmt::print(
      "\nThe default problem at five single-support meshes (SSP segments after \"at\"):\n\n");
  printHeader();
  for (int segments : {24, 27, 30, 33, 36})
    for (const Variant& v : {kTheta, kReduced12})
      printRow("mu2004_walk.yaml", v, repeats, segments);
  fmt::print("\nMedians of {} solves per row in one process (one for a solve over 2 s).\n",
             repeats);
}
