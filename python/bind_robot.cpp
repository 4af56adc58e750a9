/// @file bind_robot.cpp
/// gaitopt.Robot: the single-support dynamics D(theta) ddtheta + H(theta, dtheta) + G(theta) = tau
/// (Mu 2.6-2.8) and the energies (Mu 2.3, 2.4) of a robot YAML, with numpy arrays.
#include <pybind11/eigen.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "config/quantities.hpp"
#include "dynamics/energy.hpp"
#include "dynamics/kinematics.hpp"
#include "dynamics/model_variation.hpp"
#include "dynamics/robot_files/robot_config.hpp"
#include "dynamics/robot_files/urdf_export.hpp"
#include "dynamics/ssp_dynamics.hpp"
#include "io/data_dir.hpp"
#include "python/bindings.hpp"

namespace py = pybind11;

namespace gaitopt::python {
namespace {

using dynamics::Model;
using gaitopt::VecD;

/// A vector of finite numbers of the robot's size, or InputError (a numpy array of another length
/// would otherwise index out of bounds).
const VecD& sized(const Model& model, const VecD& v, std::string_view name) {
  if (v.size() != model.nLinks())
    throw std::invalid_argument(std::string(name) + ": expected " + std::to_string(model.nLinks()) +
                                " values (one per link), got " + std::to_string(v.size()));
  if (!v.allFinite())
    throw std::invalid_argument(std::string(name) + ": expected finite numbers, got NaN or Inf");
  return v;
}

/// Angles, rates or accelerations of the robot's size, each in the range `inspect --state`
/// takes (config/quantities.hpp), or InputError: NaN, Inf or 1e200 rad/s would otherwise come
/// back as NaN or Inf energies.
const VecD& state(const Model& model, const VecD& v, const config::Quantity& q) {
  sized(model, v, q.name);
  for (int i = 0; i < v.size(); ++i)
    config::requireInRange(q, v(i), std::string(q.name) + "[" + std::to_string(i) + "]");
  return v;
}

}  // namespace

void bindRobot(py::module_& m) {
  py::class_<Model>(m, "Robot", "A planar biped loaded from a robot YAML (configs/robots/).")
      .def(py::init([](const std::filesystem::path& path) {
             return dynamics::loadRobot(io::shippedIfMissing(path.string()));
           }),
           py::arg("path"),
           "Loads and checks a robot file; InputError names the file and key of a bad value.")
      .def_property_readonly("name", &Model::name, "the robot file's name")
      .def_property_readonly("n_links", &Model::nLinks, "links in chain order, stance tip first")
      .def_property_readonly("total_mass", &Model::totalMass, "[kg]")
      .def_property_readonly("gravity", &Model::gravity, "|g| [m/s^2]")
      .def_property_readonly("slope", &Model::slope, "ground inclination [rad], > 0 uphill")
      .def_property_readonly(
          "link_names",
          [](const Model& r) {
            std::vector<std::string> names;
            for (const auto& l : r.links()) names.push_back(l.name);
            return names;
          },
          "link names in chain order")
      .def_property_readonly(
          "link_lengths",
          [](const Model& r) {
            VecD l(r.nLinks());
            for (int i = 0; i < r.nLinks(); ++i) l(i) = r.link(i).length;
            return l;
          },
          "link lengths in chain order [m]")
      .def(
          "urdf", [](const Model& r) { return dynamics::urdfText(r, dynamics::kExportFoot); },
          "The robot as URDF text, as `gaitopt export-urdf` writes it "
          "(dynamics/robot_files/urdf_export.hpp: planar in x-z, feet of 0.05 kg added).")
      .def("with_slope", &dynamics::withSlope, py::arg("slope"),
           "The same robot on a slope [rad] (gravity rotated).")
      .def(
          "mass_matrix",
          [](const Model& r, const VecD& theta) {
            return dynamics::massMatrix<double>(r, state(r, theta, config::kLinkAngle));
          },
          py::arg("theta"), "D(theta), n x n (Mu 2.8a)")
      .def(
          "coriolis",
          [](const Model& r, const VecD& theta, const VecD& dtheta) {
            return dynamics::coriolis<double>(r, state(r, theta, config::kLinkAngle),
                                              state(r, dtheta, config::kLinkRate));
          },
          py::arg("theta"), py::arg("dtheta"), "H(theta, dtheta) (Mu 2.8b)")
      .def(
          "gravity_vector",
          [](const Model& r, const VecD& theta) {
            return dynamics::gravityVector<double>(r, state(r, theta, config::kLinkAngle));
          },
          py::arg("theta"), "G(theta) (Mu 2.8c, sign corrected: G_i = -g_i sin theta_i)")
      .def(
          "kinetic_energy",
          [](const Model& r, const VecD& theta, const VecD& dtheta) {
            return dynamics::kineticEnergy<double>(r, state(r, theta, config::kLinkAngle),
                                                   state(r, dtheta, config::kLinkRate));
          },
          py::arg("theta"), py::arg("dtheta"), "K with the stance tip pinned [J] (Mu 2.4)")
      .def(
          "potential_energy",
          [](const Model& r, const VecD& theta) {
            return dynamics::potentialEnergy<double>(r, state(r, theta, config::kLinkAngle));
          },
          py::arg("theta"), "P with the stance tip at the origin [J] (Mu 2.3)")
      .def(
          "forward_dynamics",
          [](const Model& r, const VecD& theta, const VecD& dtheta, const VecD& tau) {
            return dynamics::sspForwardDynamics(r, state(r, theta, config::kLinkAngle),
                                                state(r, dtheta, config::kLinkRate),
                                                sized(r, tau, "tau"));
          },
          py::arg("theta"), py::arg("dtheta"), py::arg("tau"),
          "ddtheta of single support under joint torques tau (q-space, tau0 the stance ankle)")
      .def(
          "inverse_dynamics",
          [](const Model& r, const VecD& theta, const VecD& dtheta, const VecD& ddtheta) {
            return dynamics::sspInverseDynamics(r, state(r, theta, config::kLinkAngle),
                                                state(r, dtheta, config::kLinkRate),
                                                state(r, ddtheta, config::kLinkAcceleration));
          },
          py::arg("theta"), py::arg("dtheta"), py::arg("ddtheta"),
          "joint torques of single support (Mu 2.43)")
      .def(
          "swing_tip",
          [](const Model& r, const VecD& theta) {
            return dynamics::swingTip<double>(r, state(r, theta, config::kLinkAngle));
          },
          py::arg("theta"), "swing tip E relative to the stance tip B [m] (Mu 2.1)");
}

}  // namespace gaitopt::python
