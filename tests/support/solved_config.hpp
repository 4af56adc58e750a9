#pragma once
/// @file solved_config.hpp
/// A gait problem built from an OCP config on its initial guess and solved once by Ipopt, in
/// place: the problem's sets point to the model, so the object is never copied or moved.
#include <string>
#include <utility>

#include "ocp/guess/initial_guess.hpp"
#include "ocp/problem/gait_problem.hpp"
#include "ocp/solve/ipopt_adapter.hpp"

namespace gaitopt::test {

/// configs/ocp/NAME.yaml of the source tree.
inline std::string shippedOcpConfig(const std::string& name) {
  return std::string(GAITOPT_SOURCE_DIR) + "/configs/ocp/" + name + ".yaml";
}

struct SolvedConfig {
  explicit SolvedConfig(ocp::OcpConfig c)
      : config(std::move(c)),
        model(ocp::problemModel(config)),
        problem(ocp::buildGaitProblem(model, config, ocp::initialGuess(model, config))),
        result(ocp::solveWithIpopt(problem.nlp, config.solver)) {}
  SolvedConfig(const SolvedConfig&) = delete;
  SolvedConfig& operator=(const SolvedConfig&) = delete;

  ocp::OcpConfig config;
  dynamics::Model model;
  ocp::GaitProblem problem;
  ocp::SolveResult result;
};

}  // namespace gaitopt::test
