#pragma once
/// @file solution_report.hpp
/// The result folder of a gait solve (`gaitopt optimize`, each point of `gaitopt library`):
/// trajectory.csv along the scheme's own polynomials, summary.json with the metrics, the
/// solver's account and the constraints between the nodes, and pictures; a failed solve goes
/// to a folder of its own, marked by FAILED.txt.
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "dynamics/model.hpp"
#include "gaits/trajectory/trajectory.hpp"
#include "ocp/solve/gait_solve.hpp"

namespace gaitopt::ocp {

/// Draws the pictures of a gait folder `dir` once its trajectory.csv and summary.json are
/// written (the caller's plot scripts); empty: no pictures.
using FolderPictures = std::function<void(const std::string& dir)>;

struct GaitResultOptions {
  std::string config_path;  ///< recorded in summary.json
  double rate_hz = 1000;    ///< of trajectory.csv
  FolderPictures pictures;
  /// The config values set on the command line (KEY=VALUE), recorded in summary.json
  std::vector<std::string> config_overrides;
  /// The result folder the solve started from (optimize --warm-start), or empty; recorded in
  /// summary.json, and never replaced by a failed solve's folder.
  std::string warm_start;
};

/// The files of every gait folder (designed, optimised or interpolated) into `dir`:
/// trajectory.csv and trajectory.json on the grid t_i = i / rate_hz, summary.json with the
/// switch states (gaits/export/gait_export.hpp), then the pictures when `pictures` is set. Returns
/// the number of samples.
size_t writeGaitFiles(const std::string& dir, const gaits::Trajectory& traj,
                      const dynamics::Model& model, double rate_hz,
                      const nlohmann::ordered_json& summary, const FolderPictures& pictures);

/// How far the constraints that hold at the collocation points are missed between them, on the
/// dense export `dense` sampled at `rate_hz`: max_dynamics_defect [N m] and per peak torque,
/// max_tip_acceleration [m/s^2] (gaits/export/consistency.hpp),
/// min_normal_force [N], max_friction_ratio (or why it is unbounded: a normal force <= 0),
/// min_zmp_margin, min_foot_cop_margin, min_swing_clearance, max_dsp_tip_drift [m],
/// max_rate_mismatch, max_acceleration_mismatch (gaits/export/export_checks.hpp), rate_hz.
nlohmann::ordered_json betweenNodeMetrics(const gaits::Trajectory& dense,
                                          const dynamics::Model& model, double rate_hz);

/// summary.json of a solution: the metrics of gaits::gaitSummary on the knots, the solver's cost,
/// iterations and violation, the impact's energy loss (impact_energy_loss_J, rigid impacts only),
/// `failure` merged in (or null), betweenNodeMetrics() of `dense`, the NLP's size, the mesh
/// history and every solver setting.
nlohmann::ordered_json solutionSummary(const GaitResultOptions& options,
                                       const dynamics::Model& model, const OcpConfig& config,
                                       const GaitSolution& solution,
                                       const nlohmann::ordered_json& failure,
                                       const gaits::Trajectory& dense);

/// Writes the files into `dir` (an existing staging folder); `failure` (or null) is merged into
/// summary.json, which is returned.
nlohmann::ordered_json writeGaitResult(const GaitResultOptions& options,
                                       const dynamics::Model& model, const OcpConfig& config,
                                       const GaitSolution& solution,
                                       const nlohmann::ordered_json& failure,
                                       const std::string& dir);

/// Removes `failed_dir` when it holds a failed solve (writeFailedResult's FAILED.txt in a
/// gaitopt folder): the old failure of a result just solved. A converged result that happens to
/// be named so is kept.
void removeFailedResult(const std::string& failed_dir);

/// Writes a failed solve's least-violated point to `failed_dir` (staged,
/// io/output/output_folder.hpp) with FAILED.txt, `"converged": false` and the worst violations;
/// returns the one-line account (status, iterations, worst constraint and bound).
std::string writeFailedResult(const GaitResultOptions& options, const dynamics::Model& model,
                              const OcpConfig& config, const GaitSolution& solution,
                              const std::string& failed_dir);

}  // namespace gaitopt::ocp
