#include "apps/optimize_command.hpp"

#include <cmath>
#include <filesystem>
#include <stdexcept>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "apps/command_runner.hpp"
#include "apps/plotting.hpp"
#include "dynamics/energy.hpp"
#include "dynamics/robot_config.hpp"
#include "gaits/consistency.hpp"
#include "gaits/gait_summary.hpp"
#include "gaits/metrics.hpp"
#include "gaits/trajectory_csv.hpp"
#include "ocp/gait_solve.hpp"
#include "ocp/initial_guess.hpp"

namespace gaitopt::apps {
namespace {

/// A previous result (warm start), or the config's polynomial gait.
gaits::Trajectory initialGuess(const dynamics::Model& model, const ocp::OcpConfig& config,
                               const std::string& warm_start) {
  if (!warm_start.empty()) return gaits::readTrajectoryCsv(warm_start + "/trajectory.csv", model);
  return ocp::polynomialGuess(model, config);
}

/// Kinetic energy lost in the strike, from the solution's own impact variables [J].
double impactLoss(const ocp::GaitProblem& p, const dynamics::Model& model,
                  const Eigen::VectorXd& x) {
  const int n = model.nLinks();
  const Eigen::VectorXd strike = p.ssp.point(x, p.ssp.points() - 1);
  const VecD theta = strike.head(n), dtheta = strike.segment(n, n);
  const Vec2d base = x.segment<2>(p.impact_offset);
  const VecD dtheta_plus = x.segment(p.impact_offset + 2, n);
  return dynamics::kineticEnergy<double>(model, theta, dtheta) -
         dynamics::kineticEnergy<double>(model, theta, dtheta_plus, base);
}

/// The worst friction ratio, or why there is none (a tip pulling on the ground).
nlohmann::ordered_json frictionRatioJson(const gaits::Trajectory& traj) {
  const double ratio = gaits::maxFrictionRatio(traj);
  if (std::isfinite(ratio) && gaits::minNormalForce(traj) > 0) return ratio;
  return "unbounded: a normal force <= 0";
}

nlohmann::ordered_json meshHistory(const std::vector<ocp::MeshRound>& history) {
  auto rounds = nlohmann::ordered_json::array();
  for (const auto& m : history)
    rounds.push_back({{"segments", m.segments},
                      {"status", m.status},
                      {"iterations", m.iterations},
                      {"cost", m.cost},
                      {"max_segment_error_Nms", m.max_segment_error},
                      {"wall_time_s", m.wall_time_s}});
  return rounds;
}

void writeResult(const OptimizeOptions& o, const dynamics::Model& model,
                 const ocp::OcpConfig& config, const ocp::GaitSolution& solution,
                 const std::string& dir) {
  const ocp::GaitProblem& problem = solution.problem;
  const ocp::SolveResult& r = solution.result;
  std::filesystem::create_directories(dir);
  const gaits::Trajectory traj = ocp::reconstruct(problem, model, r.x);
  // Between the points the export follows the scheme's own polynomials.
  const gaits::Trajectory dense = ocp::reconstructDense(problem, model, r.x, o.output.rate_hz);
  gaits::writeTrajectoryCsv(dense, model, dir + "/trajectory.csv");
  auto summary = gaits::gaitSummary(traj, model,
                                    {o.config_path, r.status, r.iterations, r.wall_time_s,
                                     r.callback_time_s, config.cost.primary()});
  summary["cost"] = r.cost;  // the solver's objective (the scheme's own quadrature)
  if (problem.impact_offset >= 0) summary["impact_energy_loss_J"] = impactLoss(problem, model, r.x);
  summary["max_violation"] = r.max_violation;
  // The constraints hold at the collocation points; the dense export shows how far they are
  // missed between them.
  summary["between_nodes"] = {{"max_dynamics_defect", gaits::maxDynamicsResidual(dense, model)},
                              {"min_normal_force", gaits::minNormalForce(dense)},
                              {"max_friction_ratio", frictionRatioJson(dense)},
                              {"min_zmp_margin", gaits::minZmpMargin(dense, model)},
                              {"rate_hz", o.output.rate_hz}};
  summary["nlp"] = {{"variables", problem.nlp.variables()},
                    {"constraints", problem.nlp.constraints()},
                    {"segments", solution.history.back().segments},
                    {"scheme", ocp::toString(problem.ssp.scheme)}};
  summary["mesh_history"] = meshHistory(solution.history);
  gaits::writeJsonFile(summary, dir + "/summary.json");
  if (o.output.plots) runPlotScript("gait_plots.py", fmt::format("'{}'", dir));
}

}  // namespace

void runOptimize(const OptimizeOptions& o) {
  ocp::OcpConfig config = ocp::loadOcpConfig(o.config_path);
  const dynamics::Model model = dynamics::loadRobot(config.robot_path);
  if (!o.quiet) fmt::print("optimize: {} on {}\n", config.name, model.name());
  config.solver.progress = !o.quiet;
  if (!o.warm_start.empty()) config.solver = ocp::warmStarted(config.solver);
  const ocp::GaitSolution solution = ocp::solveGait(
      model, config, initialGuess(model, config, o.warm_start), [&](const ocp::MeshRound& m) {
        if (!o.quiet)
          fmt::print(
              "optimize: mesh {} segments, {} after {} iterations, cost {:.6g}, max "
              "segment error {:.2e} N m s\n",
              fmt::join(m.segments, "+"), m.status, m.iterations, m.cost, m.max_segment_error);
      });
  const ocp::SolveResult& r = solution.result;
  fmt::print(
      "optimize: {} after {} iterations, cost {:.6g}, max violation {:.2e}, {:.3f} s "
      "({:.3f} s in our callbacks)\n",
      r.status, r.iterations, r.cost, r.max_violation, r.wall_time_s, r.callback_time_s);
  // A failed solve never overwrites a result: its last iterate goes to OUT.failed.
  const std::string dir = r.success ? o.output.out_dir : o.output.out_dir + ".failed";
  writeResult(o, model, config, solution, dir);
  if (!r.success)
    throw std::runtime_error(
        fmt::format("solver status {}; last iterate written to {}", r.status, dir));
  fmt::print("optimize: wrote {}/trajectory.csv, summary.json and pictures\n", dir);
}

void registerOptimizeCommand(CLI::App& app) {
  auto options = std::make_shared<OptimizeOptions>();
  CLI::App* cmd = app.add_subcommand(
      "optimize", "Solve the gait optimal control problem of a config with Ipopt");
  cmd->add_option("--config", options->config_path, "OCP YAML (configs/ocp/*.yaml)")
      ->required()
      ->option_text("FILE");
  addOutputOptions(cmd, options->output);
  cmd->add_option("--warm-start", options->warm_start,
                  "Start from the trajectory.csv of a previous result folder (same robot)")
      ->option_text("DIR");
  cmd->add_flag("--quiet", options->quiet, "No per-iteration progress");
  cmd->footer("Exit codes: 0 ok, 2 bad input, 1 solver failure (last iterate in DIR.failed).");
  cmd->callback([options] { runSubcommand([&] { runOptimize(*options); }); });
}

}  // namespace gaitopt::apps
