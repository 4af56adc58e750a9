/// @file bind_trajectory.cpp
/// gaitopt.Trajectory (gaits/trajectory/trajectory.hpp) with its knots as numpy arrays, the
/// polynomial gait of Mu ch. 3 (design_poly) and a gait folder's trajectory.csv (read_trajectory,
/// write_trajectory).
#include <filesystem>

#include <fmt/format.h>
#include <pybind11/eigen.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "config/quantities.hpp"
#include "dynamics/model_variation.hpp"
#include "gaits/export/gait_export.hpp"
#include "gaits/export/gait_folder_checks.hpp"
#include "gaits/export/gait_summary.hpp"
#include "gaits/polynomial/gait_params.hpp"
#include "gaits/polynomial/hip_plan_search.hpp"
#include "gaits/polynomial/polynomial_gait.hpp"
#include "gaits/trajectory/trajectory_csv.hpp"
#include "io/data_dir.hpp"
#include "io/output/output_folder.hpp"
#include "python/bindings.hpp"

namespace py = pybind11;

namespace gaitopt::python {
namespace {

using gaits::Knot;
using gaits::Trajectory;

/// One knot field of every knot as rows of a matrix (N x size).
template <class Field>
Eigen::MatrixXd stacked(const Trajectory& traj, Field field) {
  const auto& knots = traj.knots();
  const Eigen::Index cols = knots.empty() ? 0 : field(knots.front()).size();
  Eigen::MatrixXd out(static_cast<Eigen::Index>(knots.size()), cols);
  for (std::size_t k = 0; k < knots.size(); ++k)
    out.row(static_cast<Eigen::Index>(k)) = field(knots[k]).transpose();
  return out;
}

template <class Field>
void addMatrix(py::class_<Trajectory>& c, const char* name, Field field, const char* doc) {
  c.def_property_readonly(
      name, [field](const Trajectory& t) { return stacked(t, field); }, doc);
}

/// The polynomial gait of a gait YAML for `robot` on the gait's slope (as `gaitopt poly`).
Trajectory designPoly(const dynamics::Model& robot, const std::filesystem::path& gait_path,
                      double rate_hz) {
  config::requireInRange(config::kSampleRate, rate_hz, "rate_hz");
  const gaits::GaitParams params = gaits::loadGait(io::shippedIfMissing(gait_path.string()));
  const dynamics::Model model = dynamics::withSlope(robot, params.slope);
  const gaits::HipPlanSearch search = gaits::searchHipPlan(model, params);
  return gaits::buildTrajectory(gaits::PolynomialGait(model, params, search.plan), model, rate_hz);
}

/// A gait folder of `traj` (trajectory files and summary.json) at `dir`, by the CLI's --out rules
/// (io/output/output_folder.hpp): created, or replaced whole when gaitopt wrote it; a folder of
/// the user's own files is refused.
size_t writeFolder(const Trajectory& traj, const dynamics::Model& robot,
                   const std::filesystem::path& dir, double rate_hz) {
  config::requireInRange(config::kSampleRate, rate_hz, "rate_hz");
  requireTrajectoryOf(traj, robot);
  size_t samples = 0;
  io::OutputFolder(dir.string(), {}, "dir", "gait").write([&](const std::string& staging) {
    samples = gaits::writeGaitExport(staging, traj, robot, rate_hz,
                                     gaits::gaitSummary(traj, robot, {"", "exported"}));
  });
  return samples;
}

/// The trajectory.csv at `path`, refused (InputError) when the summary.json beside it says it is
/// a failed solve or a gait of another robot, as simulate refuses such a reference: the file
/// alone checks only the number of links.
Trajectory readFolderTrajectory(const std::filesystem::path& path, const dynamics::Model& robot) {
  const std::filesystem::path dir = path.parent_path();
  gaits::requireDesignedFor(dir.empty() ? "." : dir.string(), robot);
  return gaits::readTrajectoryCsv(path.string(), robot);
}

}  // namespace

void requireTrajectoryOf(const gaits::Trajectory& traj, const dynamics::Model& robot) {
  if (traj.robot() != robot.name())
    throw std::invalid_argument(
        fmt::format("the trajectory is a gait of robot '{}', not of "
                    "robot '{}' given with it",
                    traj.robot(), robot.name()));
}

void bindTrajectory(py::module_& m) {
  py::class_<Trajectory> c(m, "Trajectory",
                           "One step sampled on a time grid; a phase switch is two knots at "
                           "the same time (the last SSP knot, the first DSP knot).");
  c.def_property_readonly("robot", &Trajectory::robot, "the name of the robot it is a gait of")
      .def_property_readonly("step_length", &Trajectory::stepLength, "[m]")
      .def_property_readonly("duration", &Trajectory::duration, "[s]")
      .def_property_readonly("n_links", &Trajectory::nLinks, "angles per knot")
      .def_property_readonly(
          "phase_durations",
          [](const Trajectory& t) {
            std::vector<std::pair<std::string, double>> out;
            for (const auto& [phase, d] : t.phaseDurations())
              out.emplace_back(gaits::toString(phase), d);
            return out;
          },
          "(phase, duration [s]) in order: SSP, then DSP when there is one")
      .def_property_readonly(
          "t",
          [](const Trajectory& t) {
            Eigen::VectorXd out(static_cast<Eigen::Index>(t.knots().size()));
            for (std::size_t k = 0; k < t.knots().size(); ++k)
              out(static_cast<Eigen::Index>(k)) = t.knots()[k].t;
            return out;
          },
          "knot times [s], non-decreasing (a switch's two knots share one)")
      .def_property_readonly(
          "phase",
          [](const Trajectory& t) {
            std::vector<std::string> out;
            for (const Knot& k : t.knots()) out.emplace_back(toString(k.phase));
            return out;
          },
          "each knot's phase, 'SSP' or 'DSP'")
      .def(
          "resample",
          [](const Trajectory& t, double rate_hz) {
            return t.resample(config::requireInRange(config::kSampleRate, rate_hz, "rate_hz"));
          },
          py::arg("rate_hz"),
          "The step on the grid t_i = i / rate_hz with its switch and end states, as "
          "write_trajectory then read_trajectory would give it back.")
      .def("__len__", [](const Trajectory& t) { return t.knots().size(); });
  addMatrix(
      c, "theta", [](const Knot& k) { return k.theta; }, "absolute angles [rad], N x n");
  addMatrix(
      c, "dtheta", [](const Knot& k) { return k.dtheta; }, "[rad/s], N x n");
  addMatrix(
      c, "ddtheta", [](const Knot& k) { return k.ddtheta; }, "[rad/s^2], N x n");
  addMatrix(
      c, "tau", [](const Knot& k) { return k.tau; }, "joint torques [N m], N x n");
  addMatrix(
      c, "force_stance", [](const Knot& k) { return Eigen::VectorXd(k.force_stance); },
      "ground force on the stance tip [N], N x 2");
  addMatrix(
      c, "force_swing", [](const Knot& k) { return Eigen::VectorXd(k.force_swing); },
      "ground force on the swing tip [N] (zero in SSP), N x 2");

  m.def("design_poly", &designPoly, py::arg("robot"), py::arg("gait_path"),
        py::arg("rate_hz") = 1000.0,
        "The polynomial gait of Mu (2004) ch. 3 for a gait YAML (configs/gaits/); "
        "InfeasibleError when the robot cannot realise it.");
  m.def("read_trajectory", &readFolderTrajectory, py::arg("path"), py::arg("robot"),
        "Reads a trajectory.csv for the robot, with the switch states of the summary.json "
        "beside it put back; InputError when that summary names another robot or a failed "
        "solve.");
  m.def("write_trajectory", &writeFolder, py::arg("trajectory"), py::arg("robot"), py::arg("dir"),
        py::arg("rate_hz") = 1000.0,
        "Writes DIR/trajectory.csv and trajectory.json on the grid t_i = i / rate_hz and "
        "DIR/summary.json with the metrics and the switch states "
        "(docs/design.md#the-export-contract); returns the number of samples. DIR is "
        "created, or replaced whole when gaitopt wrote it, as the CLI's --out; a folder of "
        "other files is refused (InputError).");
}

}  // namespace gaitopt::python
