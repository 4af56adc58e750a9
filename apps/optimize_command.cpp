#include "apps/optimize_command.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "apps/command_runner.hpp"
#include "apps/plotting.hpp"
#include "apps/result_folder.hpp"
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

/// A step the two legs cannot span, even stretched, is bad input, not a question for Ipopt
/// (which would spend its iteration limit on it). @throws std::domain_error naming the key.
void requireReachable(const dynamics::Model& model, const ocp::OcpConfig& config,
                      const std::string& path) {
  double leg = 0;
  for (int i = 0; i < model.legLinks(); ++i) leg += model.link(i).length;
  if (config.step_length < 2 * leg) return;
  throw std::domain_error(fmt::format(
      "{}: key 'step_length': {:g} m is out of reach: the legs of robot '{}' ({:.4g} m each) "
      "span less than {:.4g} m",
      path, config.step_length, model.name(), leg, 2 * leg));
}

/// A previous result (warm start), or the config's polynomial gait.
gaits::Trajectory initialGuess(const dynamics::Model& model, const ocp::OcpConfig& config,
                               const std::string& warm_start) {
  if (!warm_start.empty()) return gaits::readTrajectoryCsv(warm_start + "/trajectory.csv", model);
  try {
    return ocp::polynomialGuess(model, config);
  } catch (const std::domain_error& e) {  // say which file holds the unrealisable gait
    throw std::domain_error(fmt::format("{}: the initial-guess gait cannot be realised: {}",
                                        config.guess_gait_path, e.what()));
  }
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

/// The location of a violation for summary.json; `name_key` says what the name names.
nlohmann::ordered_json violationJson(const ocp::LocatedViolation& v, const std::string& name_key) {
  const ocp::Violation& w = v.violation;
  if (w.name.empty()) return nullptr;
  using Json = nlohmann::ordered_json;
  const bool on_grid = v.node >= 0;
  return {{name_key, w.name},
          {"phase", v.phase},
          {"node_kind", on_grid ? Json(v.node_kind) : Json()},
          {"node", on_grid ? Json(v.node) : Json()},
          {v.part, on_grid ? v.index : w.index},
          {"value", w.value},
          {"lower", w.lower},
          {"upper", w.upper},
          {"violation", w.amount}};
}

/// Why a solve failed and where: the error line (also in FAILED.txt) and summary.json's keys.
struct FailureReport {
  std::string message;
  nlohmann::ordered_json summary;
};

FailureReport failureReport(const ocp::GaitSolution& solution, const std::string& dir) {
  const ocp::SolveResult& r = solution.result;
  const auto row = ocp::worstConstraint(solution.problem, r.x);
  const auto bound = ocp::worstBound(solution.problem, r.x);
  const std::string message = fmt::format(
      "solver status {} after {} iterations; worst violated constraint: {}; worst variable "
      "bound: {}; {} (max violation {:.3g}) written to {}",
      r.status, r.iterations, ocp::describe(row), ocp::describe(bound), r.point, r.max_violation,
      dir);
  return {message,
          {{"point", r.point},
           {"worst_violation", violationJson(row, "constraint")},
           {"worst_bound_violation", violationJson(bound, "variable")}}};
}

void writeResult(const OptimizeOptions& o, const dynamics::Model& model,
                 const ocp::OcpConfig& config, const ocp::GaitSolution& solution,
                 const nlohmann::ordered_json& failure, const std::string& dir) {
  const ocp::GaitProblem& problem = solution.problem;
  const ocp::SolveResult& r = solution.result;
  const gaits::Trajectory traj = ocp::reconstruct(problem, model, r.x);
  // Between the points the export follows the scheme's own polynomials.
  const gaits::Trajectory dense = ocp::reconstructDense(problem, model, r.x, o.output.rate_hz);
  gaits::writeTrajectoryCsv(dense, model, dir + "/trajectory.csv");
  auto summary = gaits::gaitSummary(traj, model,
                                    {o.config_path, r.status, r.iterations, r.wall_time_s,
                                     r.callback_time_s, config.cost.primary()});
  summary["converged"] = r.success;
  summary["cost"] = r.cost;  // the solver's objective (the scheme's own quadrature)
  if (problem.impact_offset >= 0) summary["impact_energy_loss_J"] = impactLoss(problem, model, r.x);
  summary["max_violation"] = r.max_violation;
  if (!failure.is_null()) summary.update(failure);
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

/// FAILED.txt, so that a person browsing the folders cannot mistake it for a gait. The folder
/// is renamed into place only when complete, so a plain write suffices.
void writeFailedNote(const std::string& path, const std::string& message) {
  std::ofstream out(path);
  out << "This folder holds a failed solve, not a gait: do not use it as a reference.\n"
      << message << '\n';
  if (!out) throw std::runtime_error("cannot write " + path);
}

/// A failed solve goes to OUT.failed, marked by FAILED.txt and `"converged": false`, and never
/// touches a previous good result in OUT. @throws CommandError with the exit code.
[[noreturn]] void reportFailure(const OptimizeOptions& o, const dynamics::Model& model,
                                const ocp::OcpConfig& config, const ocp::GaitSolution& solution) {
  const std::string failed_dir = o.output.out_dir + ".failed";
  const FailureReport report = failureReport(solution, failed_dir);
  writeResultFolder(failed_dir, [&](const std::string& dir) {
    writeResult(o, model, config, solution, report.summary, dir);
    writeFailedNote(dir + "/FAILED.txt", report.message);
  });
  const bool infeasible = solution.result.status == "Infeasible_Problem_Detected";
  throw CommandError(infeasible ? kExitInfeasible : kExitNotConverged, report.message);
}

}  // namespace

void runOptimize(const OptimizeOptions& o) {
  ocp::OcpConfig config = ocp::loadOcpConfig(o.config_path);
  const dynamics::Model model = dynamics::loadRobot(config.robot_path);
  requireReachable(model, config, o.config_path);
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
  if (!r.success) reportFailure(o, model, config, solution);
  writeResultFolder(o.output.out_dir, [&](const std::string& dir) {
    writeResult(o, model, config, solution, nullptr, dir);
  });
  // A failure of an earlier run would sit next to this result and contradict it.
  std::filesystem::remove_all(o.output.out_dir + ".failed");
  fmt::print("optimize: wrote {}/trajectory.csv, summary.json and pictures\n", o.output.out_dir);
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
  cmd->footer(
      "Exit codes: 0 ok, 2 bad input, 3 infeasible (Ipopt's local infeasibility, or a leg "
      "cannot reach in the initial guess), 4 the solver did not converge, 1 other failure. A "
      "failed solve writes its least-violated point to DIR.failed (with FAILED.txt) and never "
      "touches DIR.");
  cmd->callback([options] { runSubcommand([&] { runOptimize(*options); }); });
}

}  // namespace gaitopt::apps
