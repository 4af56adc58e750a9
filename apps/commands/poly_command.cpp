#include "apps/commands/poly_command.hpp"

#include <chrono>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

#include "apps/command_runner.hpp"
#include "apps/export_warnings.hpp"
#include "apps/shipped_file.hpp"
#include "config/config_error.hpp"
#include "config/overrides.hpp"
#include "dynamics/model_variation.hpp"
#include "dynamics/robot_files/robot_config.hpp"
#include "gaits/export/gait_summary.hpp"
#include "gaits/polynomial/hip_plan_search.hpp"
#include "gaits/polynomial/polynomial_gait.hpp"
#include "io/output/output_folder.hpp"
#include "ocp/solve/solution_report.hpp"
#include "report/plot_script.hpp"

namespace gaitopt::apps {

void runPoly(const PolyOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  const io::OutputFolder out(options.output.out_dir, {options.robot_path, options.gait_path},
                             "--out", "gait");
  const gaits::GaitParams params =
      gaits::loadGait(options.gait_path, config::parseOverrides(options.sets));
  // The gait's ground slope rotates gravity (dynamics/model.hpp).
  const dynamics::Model model =
      dynamics::withSlope(dynamics::loadRobot(options.robot_path), params.slope);
  try {  // a robot the gait cannot be designed for is bad input (exit 2), named by its file
    dynamics::requireKneedLegs(model, "the polynomial gait (Mu ch. 3)");
  } catch (const std::invalid_argument& e) {
    throw config::ConfigError(options.robot_path, "", 0, e.what());
  }
  fmt::print("poly: {} on {}: step {:.3f} m in {:.3f} s ({:.3f} m/s)\n", params.name, model.name(),
             params.step_length, params.duration(), params.speed());

  const gaits::HipPlanSearch search = gaits::designHipPlan(model, params, options.gait_path);
  fmt::print(
      "poly: hip plan by {} ({} evaluations): V_h1 {:.4f} m/s, V_h2 {:.4f} m/s, "
      "S_D0 {:.4f} m, DSP margin {:.4f} m\n",
      search.algorithm, search.evaluations, search.plan.velocity_start,
      search.plan.velocity_touchdown, search.plan.dsp_start, search.margin);

  const gaits::PolynomialGait gait(model, params, search.plan);
  const gaits::Trajectory traj = gaits::buildTrajectory(gait, model, options.output.rate_hz);
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  auto summary = gaits::gaitSummary(traj, model, {options.gait_path, "designed", 0, elapsed, 0});
  summary.update(gaits::designJson(params, search));
  if (!options.sets.empty()) summary["config_overrides"] = options.sets;
  // The export contract, judged as optimize judges an optimum's export.
  summary["between_nodes"] = ocp::betweenNodeMetrics(traj, model, options.output.rate_hz);
  size_t samples = 0;
  out.write([&](const std::string& dir) {
    samples = ocp::writeGaitFiles(dir, traj, model, options.output.rate_hz, summary,
                                  report::gaitPictures(options.output.plots));
  });
  fmt::print(
      "poly: energy {:.2f} J, CoT {:.4f}, min normal force {:.1f} N, max friction ratio "
      "{:.3f}, min ZMP margin {:.4f} m\n",
      summary["energy_J"].get<double>(), summary["cost_of_transport"].get<double>(),
      summary["min_normal_force"].get<double>(), summary["max_friction_ratio"].get<double>(),
      summary["min_zmp_margin"].get<double>());
  fmt::print("poly: wrote {}/trajectory.csv ({} samples), summary.json{}\n", out.path(), samples,
             report::holdsPictures(out.path()) ? " and pictures" : "");
  warnOfBreaches("poly", summary["between_nodes"]);
}

void registerPolyCommand(CLI::App& app) {
  auto options = std::make_shared<PolyOptions>();
  CLI::App* cmd =
      app.add_subcommand("poly", "Design the polynomial gait of Mu (2004) ch. 3 and export it");
  cmd->add_option("--robot", options->robot_path, "Robot YAML (configs/robots/*.yaml)")
      ->required()
      ->transform(orShippedFile())
      ->option_text("FILE");
  cmd->add_option("--gait", options->gait_path, "Gait YAML (configs/gaits/*.yaml)")
      ->required()
      ->transform(orShippedFile())
      ->option_text("FILE");
  addOutputOptions(cmd, options->output);
  cmd->add_option("--set", options->sets,
                  "Replace one value of the gait config, e.g. --set step_length=0.3 (repeatable; "
                  "checked as the file is, recorded in summary.json)")
      ->option_text("KEY=VALUE");
  cmd->footer(
      "Exit codes: 0 ok, 2 bad input file or usage, 3 gait cannot be realised (a leg "
      "cannot reach), 1 other failure.");
  cmd->callback([options] { runSubcommand([&] { runPoly(*options); }); });
}

}  // namespace gaitopt::apps
