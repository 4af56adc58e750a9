/// @file ocp_study_derivatives.cpp
/// What exact derivatives buy: the exact Hessian of the Lagrangian and exact Jacobian against
/// Ipopt's limited-memory (L-BFGS) Hessian, with our Jacobian or with Ipopt's finite differences
/// of the constraints on our sparsity pattern (the modes of bench/ocp_bench.cpp), from the
/// polynomial guess at the configs' tolerance. A mode that stops without converging is a row
/// with its Ipopt status: that is where it fails.
#include <fmt/format.h>

#include "bench/ocp_bench_common.hpp"
#include "bench/ocp_study.hpp"
#include "ocp/problem/gait_problem.hpp"

namespace gaitopt::bench {

namespace {

/// Failing limited-memory solves run to the iteration limit (10-60 s on the five-link
/// problem): timed once.
constexpr double kLongSolveS = 3.0;

struct Problem {
  ocp::Scheme scheme;
  int ssp_segments;
};

/// RABBIT at Kelly's (2017) 6, 15 and 25 Hermite-Simpson segments and trapezoidal at 25; the
/// five-link problem at its config's mesh.
std::vector<Problem> problemsOf(const StudyCase& c) {
  const int mesh = c.config.phases.front().segments;
  if (c.robot != "rabbit") return {{ocp::Scheme::kHermiteSimpson, mesh}};
  return {{ocp::Scheme::kHermiteSimpson, 6},
          {ocp::Scheme::kHermiteSimpson, 15},
          {ocp::Scheme::kHermiteSimpson, mesh},
          {ocp::Scheme::kTrapezoidal, mesh}};
}

}  // namespace

void derivativeStudy(const std::vector<StudyCase>& cases, int repeats, std::ostream& csv) {
  csv << "robot,scheme,ssp_segments,dsp_segments,hessian,jacobian,status,converged,iterations,"
         "cost,wall_s,callbacks_s,solves\n";
  for (const StudyCase& c : cases)
    for (const Problem& problem : problemsOf(c)) {
      ocp::OcpConfig config = withMesh(c.config, problem.ssp_segments);
      config.scheme = problem.scheme;
      const int dsp = config.phases.size() > 1 ? config.phases.back().segments : 0;
      for (const auto& [hessian, jacobian] : kDerivativeModes) {
        config.solver.hessian = hessian;
        config.solver.jacobian = jacobian;
        const ocp::GaitProblem p = ocp::buildGaitProblem(c.model, config, c.guess);
        const TimedSolve t = solveRepeated(p.nlp, config.solver, repeats, kLongSolveS);
        csv << fmt::format("{},{},{},{},{},{},{},{},{},{:.10g},{:.6g},{:.6g},{}\n", c.robot,
                           ocp::toString(problem.scheme), problem.ssp_segments, dsp, hessian,
                           jacobian, t.last.status, t.last.success ? 1 : 0, t.last.iterations,
                           t.last.cost, t.wall, t.callbacks, t.solves);
        csv.flush();
      }
    }
}

}  // namespace gaitopt::bench
