#include "apps/commands/optimize_command.hpp"

#include <filesystem>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "apps/command_runner.hpp"
#include "apps/export_warnings.hpp"
#include "apps/shipped_file.hpp"
#include "config/config_error.hpp"
#include "gaits/export/gait_folder_checks.hpp"
#include "gaits/trajectory/grid_export.hpp"
#include "gaits/trajectory/trajectory_csv.hpp"
#include "io/output/output_folder.hpp"
#include "ocp/guess/initial_guess.hpp"
#include "ocp/solve/gait_solve.hpp"
#include "ocp/solve/solution_report.hpp"
#include "report/plot_script.hpp"

namespace gaitopt::apps {
namespace {

/// A previous result (warm start), or the config's initial guess (`path`: the config file).
gaits::Trajectory initialGuess(const dynamics::Model& model, const ocp::OcpConfig& config,
                               const std::string& path, const std::string& warm_start) {
  if (!warm_start.empty()) {
    gaits::requireGaitOf(warm_start, model);
    return gaits::readTrajectoryCsv(warm_start + "/trajectory.csv", model);
  }
  try {
    return ocp::initialGuess(model, config);
  } catch (const std::domain_error& e) {  // say which file holds the unrealisable gait
    throw std::domain_error(
        fmt::format("{}: the initial-guess gait cannot be realised: {}",
                    config.guess_gait_path.empty() ? path : config.guess_gait_path, e.what()));
  } catch (const std::invalid_argument& e) {  // a straight-leg guess for a robot with knees
    throw config::ConfigError(path, "initial_guess", 0, e.what());
  }
}

ocp::GaitResultOptions resultOptions(const OptimizeOptions& o) {
  return {o.config_path, o.output.rate_hz, report::gaitPictures(o.output.plots), o.sets,
          o.warm_start};
}

/// A failed solve goes to OUT.failed and never touches a previous good result in OUT.
/// @throws io::CommandError with the exit code.
[[noreturn]] void reportFailure(const OptimizeOptions& o, const std::string& out_dir,
                                const dynamics::Model& model, const ocp::OcpConfig& config,
                                const ocp::GaitSolution& solution) {
  const std::string message =
      ocp::writeFailedResult(resultOptions(o), model, config, solution, out_dir + ".failed");
  const bool infeasible = solution.result.status == "Infeasible_Problem_Detected";
  throw io::CommandError(infeasible ? io::kExitInfeasible : io::kExitNotConverged, message);
}

}  // namespace

void runOptimize(const OptimizeOptions& o) {
  ocp::OcpConfig config = ocp::loadOcpConfig(o.config_path, config::parseOverrides(o.sets));
  std::vector<std::string> inputs = ocp::ocpInputs(config);
  inputs.insert(inputs.end(), {o.config_path, o.warm_start});
  const io::OutputFolder out(o.output.out_dir, inputs, "--out", "gait");
  const dynamics::Model model = ocp::problemModel(config);  // the robot on the config's slope
  ocp::requireReachable(model, config, o.config_path);
  gaits::requireExportRate(ocp::shortestStep(config), o.output.rate_hz);  // before, not after
  if (!o.quiet) fmt::print("optimize: {} on {}\n", config.name, model.name());
  config.solver.progress = !o.quiet;
  if (!o.warm_start.empty()) config.solver = ocp::warmStarted(config.solver);
  const ocp::GaitSolution solution = ocp::solveGait(
      model, config, initialGuess(model, config, o.config_path, o.warm_start),
      [&](const ocp::MeshRound& m) {
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
  if (!r.success) reportFailure(o, out.path(), model, config, solution);
  nlohmann::ordered_json summary;
  out.write([&](const std::string& dir) {
    summary = ocp::writeGaitResult(resultOptions(o), model, config, solution, nullptr, dir);
  });
  // A failure of an earlier run would sit next to this result and contradict it.
  ocp::removeFailedResult(out.path() + ".failed");
  fmt::print("optimize: wrote {}/trajectory.csv, summary.json{}\n", out.path(),
             report::holdsPictures(out.path()) ? " and pictures" : "");
  warnOfBreaches("optimize", summary["between_nodes"]);
}

void registerOptimizeCommand(CLI::App& app) {
  auto options = std::make_shared<OptimizeOptions>();
  CLI::App* cmd = app.add_subcommand(
      "optimize", "Solve the gait optimal control problem of a config with Ipopt");
  cmd->add_option("--config", options->config_path, "OCP YAML (configs/ocp/*.yaml)")
      ->required()
      ->transform(orShippedFile())
      ->option_text("FILE");
  addOutputOptions(cmd, options->output);
  cmd->add_option("--warm-start", options->warm_start,
                  "Start from the trajectory.csv of a previous result folder (same robot)")
      ->option_text("DIR");
  cmd->add_option("--set", options->sets,
                  "Replace one value of the config, e.g. --set phases[0].segments=24 or --set "
                  "constraints.friction_margin=0.2 (repeatable; checked as the file is, recorded "
                  "in summary.json)")
      ->option_text("KEY=VALUE");
  cmd->add_flag("--quiet", options->quiet, "No per-iteration progress");
  cmd->footer(
      "Exit codes: 0 ok, 2 bad input, 3 infeasible (Ipopt's local infeasibility, or a leg "
      "cannot reach in the initial guess), 4 the solver did not converge, 1 other failure. A "
      "failed solve writes its least-violated point to DIR.failed (with FAILED.txt) and never "
      "touches DIR.");
  cmd->callback([options] { runSubcommand([&] { runOptimize(*options); }); });
}

}  // namespace gaitopt::apps
