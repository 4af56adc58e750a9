/// @file bind_solve.cpp
/// gaitopt.optimize: an OCP config (configs/ocp/) solved as `gaitopt optimize` solves it, from the
/// config's initial guess; the solution as a dict with the trajectory.
#include <pybind11/eigen.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "config/overrides.hpp"
#include "config/quantities.hpp"
#include "gaits/export/export_contract.hpp"
#include "io/data_dir.hpp"
#include "ocp/guess/initial_guess.hpp"
#include "ocp/problem/gait_problem.hpp"
#include "ocp/problem/ocp_config.hpp"
#include "ocp/solve/gait_solve.hpp"
#include "python/bindings.hpp"

namespace py = pybind11;

namespace gaitopt::python {
namespace {

/// The export contract's breaches as summary.json's between_nodes.breaches lists them.
py::list breaches(const std::vector<gaits::ExportBreach>& list) {
  py::list out;
  for (const auto& b : list)
    out.append(py::dict(py::arg("check") = b.check, py::arg("value") = b.value,
                        py::arg("bound") = b.bound, py::arg("meaning") = b.meaning));
  return out;
}

py::dict optimize(const std::filesystem::path& config_file, double rate_hz,
                  const std::vector<std::string>& set) {
  const std::string config_path = config_file.string();
  config::requireInRange(config::kSampleRate, rate_hz, "rate_hz");
  ocp::OcpConfig config =
      ocp::loadOcpConfig(io::shippedIfMissing(config_path), config::parseOverrides(set, "set"));
  const dynamics::Model model = ocp::problemModel(config);
  ocp::requireReachable(model, config, config_path);
  config.solver.progress = false;
  const ocp::GaitSolution solution = [&] {
    py::gil_scoped_release release;  // Ipopt runs without the interpreter
    return ocp::solveGait(model, config, ocp::initialGuess(model, config));
  }();
  const ocp::SolveResult& r = solution.result;
  if (!r.success)
    throw SolveFailed(
        config_path + ": " + r.status + " after " + std::to_string(r.iterations) + " iterations",
        r.status == "Infeasible_Problem_Detected");
  py::dict out;
  out["status"] = r.status;
  out["iterations"] = r.iterations;
  out["cost"] = r.cost;
  out["max_violation"] = r.max_violation;
  out["wall_time_s"] = r.wall_time_s;
  out["robot"] = model;
  out["knots"] = ocp::reconstruct(solution.problem, model, r.x);
  const gaits::Trajectory dense = ocp::reconstructDense(solution.problem, model, r.x, rate_hz);
  out["trajectory"] = dense;
  out["breaches"] = breaches(
      gaits::exportBreaches(gaits::exportFigures(dense, model), model.friction(), rate_hz));
  out["unjudged"] = gaits::unjudgedChecks(rate_hz);
  return out;
}

}  // namespace

void bindSolve(py::module_& m) {
  m.def("optimize", &optimize, py::arg("config_path"), py::arg("rate_hz") = 1000.0,
        py::arg("set") = std::vector<std::string>{},
        "Solves an OCP config with Ipopt as `gaitopt optimize` does; `set` lists KEY=VALUE "
        "overrides as its --set does. Returns a dict: status, "
        "iterations, cost, max_violation, wall_time_s, robot (on the config's slope), knots "
        "(one per collocation point), trajectory (trajectory.csv's grid at rate_hz with the "
        "touchdown's two states and the end state put in, as read_trajectory returns it) and "
        "breaches (the bounds the trajectory breaks between the points, as summary.json's "
        "between_nodes.breaches: a list of dicts check, value, bound, meaning) and unjudged "
        "(the checks not made at this rate, as between_nodes.unjudged.checks). "
        "InputError for a bad config, InfeasibleError or NotConvergedError for a failed solve.");
}

}  // namespace gaitopt::python
