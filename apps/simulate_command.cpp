#include "apps/simulate_command.hpp"

#include <cmath>
#include <filesystem>

#include <fmt/format.h>

#include "apps/command_runner.hpp"
#include "apps/plotting.hpp"
#include "apps/reference_folder.hpp"
#include "apps/walk_record.hpp"
#include "gaits/gait_summary.hpp"
#include "io/output_folder.hpp"
#include "sim/hzd_controller.hpp"

namespace gaitopt::apps {
namespace {

constexpr double kStickFrameInterval = 0.05;  // [s]

nlohmann::ordered_json poincareJson(const std::optional<sim::PoincareAnalysis>& p) {
  nlohmann::ordered_json j;
  if (!p) {
    j["poincare_max_multiplier"] = nullptr;
    j["poincare_multipliers"] = nullptr;
    return j;
  }
  if (!p->ok) {
    j["poincare_max_multiplier"] = nullptr;
    j["poincare_multipliers"] = nullptr;
    j["poincare_failure"] = p->failure;
    return j;
  }
  auto multipliers = nlohmann::ordered_json::array();
  for (const auto& z : p->multipliers) multipliers.push_back({z.real(), z.imag()});
  j["poincare_max_multiplier"] = p->max_multiplier;
  j["poincare_multipliers"] = multipliers;
  j["poincare_fixed_point_residual"] = p->fixed_point_residual;
  return j;
}

/// HZD's restricted Poincare map (sim/hzd_poincare.hpp): analytic, and measured on the walk.
nlohmann::ordered_json hzdJson(const sim::ScenarioResult& r) {
  const sim::RestrictedMap& a = *r.hzd_map;
  nlohmann::ordered_json j{
      {"phase_weights", std::vector<double>(a.phase_weights.begin(), a.phase_weights.end())},
      {"phase_plus", a.phi_plus},
      {"phase_minus", a.phi_minus},
      {"restricted_multiplier", a.multiplier},
      {"delta_zero", a.delta},
      {"v_zero_minus", a.v_minus},
      {"v_zero_max", a.v_max},
      {"zeta_minus_fixed_point", a.zeta_minus},
      {"phase_rate_at_touchdown", a.phidot_minus},
      {"hybrid_zero_dynamics_walk", a.walks}};
  if (r.hzd_measured && r.hzd_measured->ok)
    j["restricted_multiplier_measured"] = r.hzd_measured->multiplier;
  else if (r.hzd_measured)
    j["restricted_multiplier_measured_failure"] = r.hzd_measured->failure;
  return j;
}

/// Mean step length and duration over the completed steps.
nlohmann::ordered_json gaitJson(const sim::WalkResult& w) {
  if (w.steps_completed == 0) return {{"mean_step_length", nullptr}, {"mean_speed", nullptr}};
  const sim::WalkTotals total = sim::completedTotals(w);
  return {{"mean_step_length", total.distance / w.steps_completed},
          {"mean_step_duration", total.duration / w.steps_completed},
          {"mean_speed", total.distance / total.duration}};
}

nlohmann::ordered_json summaryJson(const SimulateOptions& o, const ReferenceFolder& ref,
                                   const sim::Scenario& s, const dynamics::Model& plant,
                                   const sim::ScenarioResult& r) {
  nlohmann::ordered_json j{{"robot", ref.model.name()}, {"robot_file", ref.robot_path}};
  j.update(scenarioJson(o.scenario, s));
  j["friction"] = plant.friction();
  j["steps_completed"] = r.walk.steps_completed;
  j["fell"] = r.walk.fell;
  j["failure"] = r.walk.failure;
  j["max_tracking_error"] = r.walk.max_tracking_error;
  j.update(gaitJson(r.walk));
  j.update(poincareJson(r.poincare));
  if (r.hzd_map) j["hzd"] = hzdJson(r);
  j["wall_time_s"] = r.wall_time_s;
  return j;
}

/// The gait HZD needs (no DSP, every joint but the ankle actuated, a growing phase variable) is
/// an input requirement: exit 2 naming the option and the folder.
void checkHzdReference(const ReferenceFolder& ref, const sim::Reference& reference) {
  try {
    sim::makeHzdController(ref.model, reference, nullptr);
  } catch (const std::invalid_argument& e) {
    throw CommandError(kExitInputError, fmt::format("--controller hzd: {}: {}", ref.dir, e.what()));
  }
}

void printOutcome(const sim::ScenarioResult& r, int steps) {
  fmt::print("simulate: {} of {} steps{}, max tracking error {:.3g} rad, {:.2f} s\n",
             r.walk.steps_completed, steps,
             r.walk.fell ? fmt::format(" then fell ({})", r.walk.failure) : "",
             r.walk.max_tracking_error, r.wall_time_s);
  if (r.poincare && r.poincare->ok)
    fmt::print("simulate: Poincare map: largest multiplier {:.4g} ({})\n",
               r.poincare->max_multiplier, r.poincare->max_multiplier < 1 ? "stable" : "unstable");
  else if (r.poincare)
    fmt::print("simulate: Poincare map failed: {}\n", r.poincare->failure);
  if (r.hzd_map)
    fmt::print("simulate: HZD restricted multiplier {:.4g} analytic{}\n", r.hzd_map->multiplier,
               r.hzd_measured && r.hzd_measured->ok
                   ? fmt::format(", {:.4g} measured", r.hzd_measured->multiplier)
                   : "");
}

}  // namespace

void runSimulate(const SimulateOptions& o) {
  const io::OutputFolder out(o.output.out_dir, scenarioInputs(o.scenario));
  const ReferenceFolder ref = loadReferenceFolder(o.scenario.reference_dir, o.scenario.robot_path);
  requireControllerFits(o.scenario, ref.model);
  sim::Scenario scenario = makeScenario(o.scenario);
  scenario.poincare = o.poincare && !scenario.push;  // a pushed walk has no periodic cycle
  const dynamics::Model plant = sim::scenarioPlant(ref.model, scenario);
  if (!o.quiet)
    fmt::print("simulate: {} steps of {} with {} on {} ground\n", scenario.steps, ref.dir,
               scenario.controller, sim::groundName(scenario.ground));
  const sim::Reference reference(ref.step);
  if (scenario.controller == "hzd") checkHzdReference(ref, reference);
  WalkRecorder recorder(plant, o.output.rate_hz);
  const sim::ScenarioResult r = sim::runScenario(ref.model, reference, scenario, recorder.log());
  recorder.finish();
  printOutcome(r, scenario.steps);
  out.write([&](const std::string& dir) {
    recorder.writeWalkCsv(dir + "/walk.csv");
    recorder.writeStickCsv(dir + "/stick.csv", kStickFrameInterval);
    writeStepsCsv(r.walk, dir + "/steps.csv");
    gaits::writeJsonFile(summaryJson(o, ref, scenario, plant, r), dir + "/summary.json");
  });
  if (o.output.plots) runPlotScript("walk_plots.py", {out.path()});
  fmt::print("simulate: wrote {}/walk.csv, steps.csv, stick.csv, summary.json\n", out.path());
}

void registerSimulateCommand(CLI::App& app) {
  auto options = std::make_shared<SimulateOptions>();
  CLI::App* cmd =
      app.add_subcommand("simulate", "Walk an exported gait in closed loop and measure it");
  addScenarioOptions(cmd, options->scenario);
  addOutputOptions(cmd, options->output);
  cmd->add_flag("!--no-poincare", options->poincare, "Skip the Poincare map of the cycle");
  cmd->add_flag("--quiet", options->quiet, "Less output");
  cmd->footer(
      "A fall is a result, not an error: exit 0 with \"fell\": true in summary.json.\n"
      "Exit codes: 0 ok, 2 bad input, 3 infeasible input, 1 other failure.");
  cmd->callback([options] { runSubcommand([&] { runSimulate(*options); }); });
}

}  // namespace gaitopt::apps
