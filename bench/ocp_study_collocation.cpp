/// @file ocp_study_collocation.cpp
/// Speed against accuracy of trapezoidal and Hermite-Simpson collocation under mesh refinement.
/// Accuracy is measured independently of the transcription (ocp/solve/resimulation.hpp): the
/// optimal torques, read along the scheme's own interpolation, are re-simulated by an adaptive RKF
/// 7(8) at 1e-12, from the solution's first SSP state over the whole SSP (the global error, whose
/// order is 2 for trapezoidal and 4 for Hermite-Simpson: Betts 2010, sec. 4.5; Kelly 2017,
/// sec. 4), and segment by segment from the solution's state at each segment start (the local
/// error, order 3 and 5, unaffected by the open-loop instability of single support).
#include <fmt/format.h>

#include "bench/ocp_bench_common.hpp"
#include "bench/ocp_study.hpp"
#include "ocp/problem/gait_problem.hpp"
#include "ocp/solve/resimulation.hpp"

namespace gaitopt::bench {

namespace {

/// A solve slower than this is not repeated: its time is known well enough, and the five-link
/// fine meshes would otherwise dominate the run.
constexpr double kLongSolveS = 5.0;
/// Integrator tolerance: the errors agree to all printed digits with 1e-13.
constexpr double kResimulationTolerance = 1e-12;

void row(const StudyCase& c, const ocp::OcpConfig& config, int repeats, std::ostream& csv) {
  const ocp::GaitProblem p = ocp::buildGaitProblem(c.model, config, c.guess);
  const TimedSolve t = solveRepeated(p.nlp, config.solver, repeats, kLongSolveS);
  const ocp::StateError end = ocp::sspEndStateError(p, c.model, t.last.x, kResimulationTolerance);
  const ocp::StateError seg = ocp::sspSegmentError(p, c.model, t.last.x, kResimulationTolerance);
  const int dsp = config.phases.size() > 1 ? config.phases.back().segments : 0;
  csv << fmt::format("{},{},{},{},{},{},{:.10g},{:.6g},{},{:.6g},{:.6g},{:.6g},{:.6g},{:.3g}\n",
                     c.robot, ocp::toString(config.scheme), config.phases.front().segments, dsp,
                     t.last.status, t.last.iterations, t.last.cost, t.wall, t.solves, end.angle,
                     end.rate, seg.angle, seg.rate, t.last.max_violation);
  csv.flush();
}

}  // namespace

void collocationStudy(const std::vector<StudyCase>& cases, int repeats, double tolerance,
                      std::ostream& csv) {
  csv << "robot,scheme,ssp_segments,dsp_segments,status,iterations,cost,wall_s,solves,"
         "end_angle_error_rad,end_rate_error_rad_s,segment_angle_error_rad,"
         "segment_rate_error_rad_s,max_violation\n";
  for (const StudyCase& c : cases)
    for (const auto scheme : {ocp::Scheme::kTrapezoidal, ocp::Scheme::kHermiteSimpson})
      for (const int ssp : c.ssp_meshes) {
        ocp::OcpConfig config = withMesh(c.config, ssp);
        config.scheme = scheme;
        config.solver.tolerance = tolerance;
        row(c, config, repeats, csv);
      }
}

}  // namespace gaitopt::bench
