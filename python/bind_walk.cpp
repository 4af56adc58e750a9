/// @file bind_walk.cpp
/// gaitopt.simulate: a closed-loop walk of a reference gait (sim/scenario/scenario.hpp), every
/// logged sample as numpy arrays and one entry per step; gaitopt.controllers and gaitopt.grounds:
/// the names it accepts, from the registries (sim/controllers/controller_registry.hpp,
/// sim/walk/ground_registry.hpp).
#include <limits>

#include <pybind11/eigen.h>
#include <pybind11/stl.h>

#include <fmt/format.h>

#include "config/quantities.hpp"
#include "python/bindings.hpp"
#include "sim/contact/ground_config.hpp"
#include "sim/scenario/scenario.hpp"
#include "sim/scenario/scenario_settings.hpp"
#include "sim/scenario/walk_memory.hpp"
#include "sim/walk/ground_registry.hpp"

namespace py = pybind11;

namespace gaitopt::python {
namespace {

py::dict samplesDict(const std::vector<sim::WalkSample>& samples, int n) {
  const auto rows = static_cast<Eigen::Index>(samples.size());
  Eigen::VectorXd t(rows), stance_x(rows);
  Eigen::VectorXi step(rows);
  Eigen::MatrixXd theta(rows, n), theta_ref(rows, n), tau(rows, n);
  std::vector<std::string> phase;
  for (Eigen::Index k = 0; k < rows; ++k) {
    const sim::WalkSample& s = samples[static_cast<std::size_t>(k)];
    t(k) = s.t;
    step(k) = s.step + 1;
    stance_x(k) = s.stance_x;
    theta.row(k) = s.theta.transpose();
    theta_ref.row(k) = s.theta_ref.transpose();
    tau.row(k) = s.tau.transpose();
    phase.emplace_back(gaits::toString(s.phase));
  }
  py::dict out;
  out["t"] = t;
  out["step"] = step;
  out["phase"] = phase;
  out["stance_x"] = stance_x;
  out["theta"] = theta;
  out["theta_ref"] = theta_ref;
  out["tau"] = tau;
  return out;
}

/// Runs Python's signal handlers (Ctrl-C, signal.alarm) from a walk that released the GIL:
/// Python runs them only when asked, so a long walk could not be interrupted otherwise.
void checkInterrupts() {
  const py::gil_scoped_acquire gil;
  if (PyErr_CheckSignals() != 0) throw py::error_already_set();
}

/// Refuses a sample no returned array may hold: a diverged walk is a failure, not NaN arrays.
void requireFinite(const sim::WalkSample& s) {
  if (!s.theta.allFinite() || !s.tau.allFinite())
    throw std::runtime_error(fmt::format(
        "simulate: the walk diverged (non-finite angles or torques at t = {:.4g} s)", s.t));
}

/// Name -> description of each registered entry, in registration order.
template <class Entry>
py::dict entryDict(const std::vector<Entry>& entries) {
  py::dict out;
  for (const Entry& e : entries) out[py::str(e.name)] = e.description;
  return out;
}

py::dict simulate(const dynamics::Model& robot, const gaits::Trajectory& reference, int steps,
                  const std::string& controller, double gain_scale, const std::string& ground) {
  sim::Scenario scenario;
  scenario.steps = static_cast<int>(config::requireInRange(config::kSteps, steps, "steps"));
  scenario.controller = controller;
  scenario.ground = sim::loadGround(sim::groundPath(ground));
  scenario.gain_scale = config::requireInRange(config::kGainScale, gain_scale, "gain_scale");
  requireTrajectoryOf(reference, robot);
  // Every sample is kept, at the ground's own step.
  sim::requireWalkFits(scenario, reference.endTime(), std::numeric_limits<double>::infinity(),
                       "steps");
  std::vector<sim::WalkSample> samples;
  const sim::ScenarioResult result = [&] {
    py::gil_scoped_release release;
    return sim::runScenario(robot, sim::Reference(reference, robot), scenario,
                            [&](const sim::WalkSample& s) {
                              checkInterrupts();
                              requireFinite(s);
                              samples.push_back(s);
                            });
  }();
  py::list step_list;
  for (const sim::StepResult& s : result.walk.steps)
    step_list.append(py::dict(
        py::arg("ok") = s.ok, py::arg("failure") = s.failure, py::arg("impact") = s.impact,
        py::arg("ssp_duration") = s.ssp_duration, py::arg("dsp_duration") = s.dsp_duration,
        py::arg("advance") = s.advance, py::arg("max_tracking_error") = s.max_tracking_error));
  py::dict out = samplesDict(samples, robot.nLinks());
  out["steps_completed"] = result.walk.steps_completed;
  out["fell"] = result.walk.fell;
  out["failure"] = result.walk.failure;
  out["max_tracking_error"] = result.walk.max_tracking_error;
  out["steps"] = step_list;
  return out;
}

}  // namespace

void bindWalk(py::module_& m) {
  m.def("simulate", &simulate, py::arg("robot"), py::arg("reference"), py::arg("steps") = 5,
        py::arg("controller") = sim::kDefaultController, py::arg("gain_scale") = 1.0,
        py::arg("ground") = sim::kDefaultGround,
        "Walks `reference` (a Trajectory of `robot`) under `controller` (a name of controllers()) "
        "on `ground` (a name of grounds() or a ground YAML), as `gaitopt simulate` (steps and "
        "gain_scale in its ranges; Ctrl-C interrupts). Returns a dict: t, step, phase, stance_x, "
        "theta, theta_ref, tau (every logged sample), steps (one dict per step), "
        "steps_completed, fell, failure, max_tracking_error.");
  m.def(
      "controllers", [] { return entryDict(sim::controllers()); },
      "The controllers simulate accepts (`gaitopt simulate --controller`): a dict of name -> "
      "one-line description, in registration order.");
  m.def(
      "grounds", [] { return entryDict(sim::grounds()); },
      "The grounds simulate accepts by name (`gaitopt simulate --ground`, "
      "configs/grounds/NAME.yaml): a dict of name -> one-line description.");
}

}  // namespace gaitopt::python
