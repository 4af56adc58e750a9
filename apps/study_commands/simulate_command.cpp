#include "apps/study_commands/simulate_command.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>

#include <fmt/format.h>

#include "apps/command_runner.hpp"
#include "config/config_error.hpp"
#include "gaits/export/gait_summary.hpp"
#include "io/output/output_folder.hpp"
#include "io/terminal_text.hpp"
#include "report/plot_script.hpp"
#include "sim/scenario/reference_folder.hpp"
#include "sim/scenario/walk_memory.hpp"
#include "sim/scenario/walk_summary.hpp"
#include "sim/walk/ground_registry.hpp"
#include "sim/walk/walk_record.hpp"

namespace gaitopt::apps {
namespace {

constexpr double kStickFrameInterval = 0.05;  // [s]

/// Walks this long say how far they are: a tenth of the steps at a time (a walk of 3000 steps
/// said nothing for 80 s).
constexpr int kProgressSteps = 100;

/// `log`, and one line on stdout each time the walk passes another tenth of its `steps`.
sim::WalkLog withStepProgress(sim::WalkLog log, int steps) {
  if (steps < kProgressSteps) return log;
  const auto start = std::chrono::steady_clock::now();
  return [log = std::move(log), steps, start, shown = 0](const sim::WalkSample& s) mutable {
    log(s);
    const int tenth = 10 * s.step / steps;
    if (tenth <= shown) return;
    shown = tenth;
    fmt::print("simulate: step {} of {}, {:.0f} s\n", s.step, steps,
               std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  };
}

void printOutcome(const sim::ScenarioResult& r, int steps) {
  fmt::print("simulate: {} of {} steps{}, max tracking error {:.3g} rad, {:.2f} s\n",
             r.walk.steps_completed, steps,
             r.walk.fell ? fmt::format(" then fell ({})", r.walk.failure) : "",
             r.walk.max_tracking_error, r.wall_time_s);
  if (r.poincare && r.poincare->ok)
    fmt::print(
        "simulate: Poincare map at step clock {:.3g} s: largest multiplier {:.4g} ({}), gait "
        "sensitivity norm of a push {:.4g}\n",
        r.poincare->section_clock, r.poincare->max_multiplier,
        r.poincare->max_multiplier < 1 ? "stable" : "unstable", r.poincare->gait_sensitivity_norm);
  else if (r.poincare)
    fmt::print("simulate: Poincare map failed: {}\n", r.poincare->failure);
  if (r.hzd_map)
    fmt::print("simulate: HZD restricted multiplier {:.4g} analytic{}\n", r.hzd_map->multiplier,
               r.hzd_measured && r.hzd_measured->ok
                   ? fmt::format(", {:.4g} measured", r.hzd_measured->multiplier)
                   : "");
}

/// Deeper than this, a swing tip below the rigid ground is a contact the walk ignored [m].
constexpr double kPenetrationWarning = 1e-4;

/// The rigid ground has no contact for a swing tip below it behind the stance tip (touchdown is
/// only ahead of it): said, not failed, so which walks fail stays as it was.
void warnPenetration(const sim::WalkResult& walk) {
  if (!(walk.max_tip_penetration > kPenetrationWarning)) return;  // NaN: not rigid
  fmt::print(
      "simulate: warning: a swing tip went {:.3g} mm below the ground (deepest in step {}), a "
      "contact the rigid ground does not model: the walk is not physical there\n",
      1e3 * walk.max_tip_penetration, sim::deepestPenetrationStep(walk));
}

}  // namespace

void runSimulate(const SimulateOptions& o) {
  const sim::ReferenceFolder ref = sim::loadReferenceFolder(
      o.scenario.reference_dir, o.scenario.robot_path, sim::robotOverrides(o.scenario));
  const io::OutputFolder out(o.output.out_dir, sim::scenarioInputs(o.scenario, ref), "--out",
                             "walk");
  sim::requireControllerFits(o.scenario, ref.model);
  sim::Scenario scenario = sim::makeScenario(o.scenario);
  scenario.poincare = o.poincare && !scenario.push;  // a pushed walk has no periodic cycle
  const dynamics::Model plant = sim::scenarioPlant(ref.model, scenario);
  if (!o.quiet)
    fmt::print("simulate: {} of {} with {} on {} ground\n", io::counted(scenario.steps, "step"),
               ref.dir, scenario.controller, sim::groundName(scenario.ground));
  const sim::Reference reference(ref.step, ref.model);
  checkControllerFitsReference(ref, reference, scenario);
  sim::requireWalkFits(scenario, reference.endTime(), o.output.rate_hz, "--steps");
  sim::WalkRecorder recorder(plant, o.output.rate_hz);
  const sim::WalkLog log =
      o.quiet ? recorder.log() : withStepProgress(recorder.log(), scenario.steps);
  const sim::ScenarioResult r = sim::runScenario(ref.model, reference, scenario, log);
  recorder.finish();
  printOutcome(r, scenario.steps);
  out.write([&](const std::string& dir) {
    recorder.writeWalkCsv(dir + "/walk.csv");
    recorder.writeStickCsv(dir + "/stick.csv", kStickFrameInterval);
    sim::writeStepsCsv(r.walk, dir + "/steps.csv");
    gaits::writeJsonFile(sim::walkSummary(o.scenario, ref, scenario, plant, r),
                         dir + "/summary.json");
  });
  if (o.output.plots) {
    report::runPlotScript("walk_plots.py", {out.path()}, report::scriptOutput(o.quiet));
    io::listAddedFiles(out.path());  // the pictures: a rerun may replace them
  }
  fmt::print("simulate: wrote {}/walk.csv, steps.csv, stick.csv, summary.json\n", out.path());
  warnPenetration(r.walk);
}

void registerSimulateCommand(CLI::App& app) {
  auto options = std::make_shared<SimulateOptions>();
  CLI::App* cmd =
      app.add_subcommand("simulate", "Walk an exported gait in closed loop and measure it");
  addScenarioOptions(cmd, options->scenario);
  // walk.csv keeps the simulator's own states, thinned to the rate: no finer than the ground's
  // time step (the rigid ground's output step, the others' integration step).
  addOutputOptions(cmd, options->output, "walk.csv, at most one row per time step of the ground");
  cmd->add_flag("!--no-poincare", options->poincare, "Skip the Poincare map of the cycle");
  cmd->add_flag("--quiet", options->quiet, "Less output");
  cmd->footer(
      "A fall is a result, not an error: exit 0 with \"fell\": true in summary.json.\n"
      "Exit codes: 0 ok, 2 bad input, 3 infeasible input, 1 other failure.");
  cmd->callback([options] { runSubcommand([&] { runSimulate(*options); }); });
}

}  // namespace gaitopt::apps
