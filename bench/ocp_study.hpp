#pragma once
/// @file ocp_study.hpp
/// The collocation study: what a scheme, a mesh, a derivative mode and an initial
/// guess cost (Ipopt iterations, wall time) and buy (accuracy, convergence), on the RABBIT
/// benchmark (configs/ocp/rabbit_kelly2017.yaml, Kelly 2017) and the default five-link problem
/// (configs/ocp/mu2004_walk.yaml). Each study prints one CSV to stdout
/// (plots/ocp_study_charts.py draws and tabulates them).
#include <ostream>
#include <string>
#include <vector>

#include "dynamics/model.hpp"
#include "gaits/trajectory/trajectory.hpp"
#include "ocp/problem/ocp_config.hpp"

namespace gaitopt::bench {

/// One of the study's problems with its polynomial initial guess (ocp::polynomialGuess).
struct StudyCase {
  std::string robot;  ///< "rabbit" or "five_link", the CSV's robot column
  ocp::OcpConfig config;
  dynamics::Model model;
  gaits::Trajectory guess;
  std::vector<int> ssp_meshes;  ///< SSP segment counts of the collocation study, coarse to fine
};

/// The RABBIT and five-link cases, configs read from the source tree.
std::vector<StudyCase> studyCases();

/// `config` with `ssp` SSP segments and the DSP (if any) scaled in proportion to the config's
/// own SSP/DSP ratio (at least one segment).
ocp::OcpConfig withMesh(ocp::OcpConfig config, int ssp);

/// Both schemes on every mesh at Ipopt tolerance `tolerance`: solve time (median of `repeats`),
/// iterations, cost, and the re-simulated end-of-SSP and per-segment state errors
/// (ocp/solve/resimulation.hpp).
void collocationStudy(const std::vector<StudyCase>& cases, int repeats, double tolerance,
                      std::ostream& csv);

/// Exact Hessian + Jacobian, limited-memory Hessian, limited-memory + finite-difference
/// Jacobian on the config meshes (and RABBIT at 6 and 15 segments), both schemes.
void derivativeStudy(const std::vector<StudyCase>& cases, int repeats, std::ostream& csv);

/// Polynomial guess, a naive straight-line guess, and `seeds` random perturbations of the
/// optimum per noise level: one row per attempt.
void guessStudy(const std::vector<StudyCase>& cases, int seeds, std::ostream& csv);

}  // namespace gaitopt::bench
