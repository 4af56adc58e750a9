#pragma once
/// @file gait_result.hpp
/// The result folder of a gait solve (`gaitopt optimize`, each point of `gaitopt library`):
/// trajectory.csv along the scheme's own polynomials, summary.json with the metrics, the
/// solver's account and the constraints between the nodes, and pictures; a failed solve goes
/// to a folder of its own, marked by FAILED.txt.
#include <string>

#include <nlohmann/json.hpp>

#include "dynamics/model.hpp"
#include "gaits/trajectory.hpp"
#include "ocp/gait_solve.hpp"

namespace gaitopt::apps {

struct GaitResultOptions {
  std::string config_path;  ///< recorded in summary.json
  double rate_hz = 1000;    ///< of trajectory.csv
  bool plots = true;
};

/// The files of every gait folder (designed, optimised or interpolated) into `dir`:
/// trajectory.csv, summary.json and, when `plots`, the pictures (gait_plots.py).
void writeGaitFiles(const std::string& dir, const gaits::Trajectory& traj,
                    const dynamics::Model& model, const nlohmann::ordered_json& summary,
                    bool plots);

/// Writes the files into `dir` (an existing staging folder); `failure` (or null) is merged into
/// summary.json, which is returned.
nlohmann::ordered_json writeGaitResult(const GaitResultOptions& options,
                                       const dynamics::Model& model, const ocp::OcpConfig& config,
                                       const ocp::GaitSolution& solution,
                                       const nlohmann::ordered_json& failure,
                                       const std::string& dir);

/// Writes a failed solve's least-violated point to `failed_dir` (staged, result_folder.hpp) with
/// FAILED.txt, `"converged": false` and the worst violations; returns the one-line account
/// (status, iterations, worst constraint and bound).
std::string writeFailedResult(const GaitResultOptions& options, const dynamics::Model& model,
                              const ocp::OcpConfig& config, const ocp::GaitSolution& solution,
                              const std::string& failed_dir);

}  // namespace gaitopt::apps
