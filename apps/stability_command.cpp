#include "apps/stability_command.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>

#include <fmt/format.h>

#include "apps/command_runner.hpp"
#include "config/config_error.hpp"
#include "gaits/gait_summary.hpp"
#include "gaits/grid_range.hpp"
#include "io/output_folder.hpp"
#include "io/settings_record.hpp"
#include "parallel/progress_bar.hpp"
#include "report/plot_script.hpp"
#include "sim/reference_folder.hpp"
#include "sim/sweep_study.hpp"

namespace gaitopt::apps {
namespace {

struct Sweep {
  const sim::SweepParameter* parameter;
  std::vector<double> values;
  std::unique_ptr<sim::SweepFile> file;
};

struct Point {
  Sweep* sweep;
  double value;
};

/// NAME or NAME=a:b:n, checked against the scenario (stiffness needs the impedance ground).
Sweep parseSweep(const std::string& text, const std::string& out_dir, sim::Scenario base) {
  const std::size_t eq = text.find('=');
  const std::string name = text.substr(0, eq);
  const sim::SweepParameter* p = nullptr;
  try {
    p = &sim::sweepParameter(name);
  } catch (const std::invalid_argument& e) {
    throw config::ConfigError("--sweep", name, 0, e.what());
  }
  const gaits::GridAxis axis = eq == std::string::npos
                                   ? gaits::GridAxis{p->first, p->last, p->count}
                                   : gaits::parseRange(text.substr(eq + 1), "--sweep " + name, 1.0);
  try {
    sim::setSweepValue(base, name, axis.first);
  } catch (const std::invalid_argument& e) {
    throw config::ConfigError("--sweep", name, 0, e.what());
  }
  Sweep s{p, {}, std::make_unique<sim::SweepFile>(out_dir + "/sweep_" + name + ".csv")};
  try {
    s.values = sim::sweepValues(*p, axis);
  } catch (const std::invalid_argument& e) {
    throw config::ConfigError("--sweep", name, 0, e.what());
  }
  return s;
}

void printInterval(const std::string& name, const nlohmann::ordered_json& j) {
  if (j["walks_from"].is_null()) {
    fmt::print("stability: {}: no walking interval around the nominal value\n", name);
    return;
  }
  fmt::print("stability: {}: walks from {:.4g} to {:.4g} {}\n", name, j["walks_from"].get<double>(),
             j["walks_to"].get<double>(), j["unit"].get<std::string>());
  for (const char* side : {"fails_below", "fails_above"})
    if (j.contains(side))
      fmt::print("  at {:.4g}: {}\n", j[side]["value"].get<double>(),
                 j[side]["failure"].get<std::string>());
}

}  // namespace

void runStability(const StabilityOptions& o) {
  const sim::ReferenceFolder ref =
      sim::loadReferenceFolder(o.scenario.reference_dir, o.scenario.robot_path);
  sim::requireControllerFits(o.scenario, ref.model);
  const sim::Reference reference(ref.step, ref.model);
  sim::Scenario base = sim::makeScenario(o.scenario);
  base.poincare = o.poincare;
  const io::ResumableFolder folder(o.out_dir, sim::scenarioInputs(o.scenario));
  const std::string& out_dir = folder.path();
  io::claimSettings(out_dir + "/settings.json", sim::sweepFolderSettings(o.scenario, ref, base));
  std::vector<Sweep> sweeps;
  for (const auto& text : o.sweeps) sweeps.push_back(parseSweep(text, out_dir, base));
  std::vector<Point> todo;
  std::size_t done_before = 0;
  for (auto& s : sweeps)
    for (double v : s.values) {
      if (s.file->has(v))
        ++done_before;
      else
        todo.push_back({&s, v});
    }
  // No more workers than points: a sweep of 2 points starts 2 threads, not one per core.
  const int jobs = static_cast<int>(
      std::min<std::size_t>(parallel::resolveJobs(o.jobs), std::max<std::size_t>(todo.size(), 1)));
  fmt::print("stability: {} points to walk ({} done before) with {} job(s)\n", todo.size(),
             done_before, jobs);
  std::fflush(stdout);
  parallel::parallelFor(
      todo.size(), jobs,
      [&](std::size_t i) {
        const Point& p = todo[i];
        p.sweep->file->append(
            sim::walkSweepPoint(ref.model, reference, base, p.sweep->parameter->name, p.value));
      },
      parallel::progressBar("stability", o.quiet));
  nlohmann::ordered_json summary{{"robot", ref.model.name()}};
  summary.update(sim::scenarioJson(o.scenario, base));
  for (const auto& s : sweeps) {
    double nominal = sim::sweepValue(base, s.parameter->name);
    if (s.parameter->name == "friction" && !std::isfinite(nominal)) nominal = ref.model.friction();
    summary["sweeps"][s.parameter->name] =
        sim::walkingInterval(*s.parameter, s.file->rows(), nominal);
    printInterval(s.parameter->name, summary["sweeps"][s.parameter->name]);
  }
  gaits::writeJsonFile(summary, out_dir + "/summary.json");
  if (o.plots) report::runPlotScript("stability_plots.py", {out_dir});
  fmt::print("stability: wrote {}/summary.json and sweep_*.csv\n", out_dir);
}

void registerStabilityCommand(CLI::App& app) {
  auto options = std::make_shared<StabilityOptions>();
  CLI::App* cmd = app.add_subcommand(
      "stability",
      "Sweep push, model error, friction, ground stiffness or gains: where walking stops");
  addScenarioOptions(cmd, options->scenario);
  std::string names;
  for (const auto& p : sim::sweepParameters())
    names += fmt::format("\n  {}{}: {} (default {}:{}:{}{})", p.name,
                         p.unit.empty() ? "" : " [" + p.unit + "]", p.meaning, p.first, p.last,
                         p.count, p.geometric ? ", geometric spacing" : "");
  cmd->add_option("--sweep", options->sweeps, "NAME or NAME=a:b:n, repeatable:" + names)
      ->required()
      ->option_text("NAME[=a:b:n]");
  cmd->add_option("--out", options->out_dir, "Result folder (created; reruns resume in it)")
      ->required()
      ->option_text("DIR");
  cmd->add_option("--jobs", options->jobs, "Worker threads (default: all cores)")
      ->check(CLI::Range(1, 1024));
  cmd->add_flag(
      "--poincare", options->poincare,
      "Also the Poincare multipliers of every point (rigid ground; ~2 n + 16 steps more)");
  cmd->add_flag("--quiet", options->quiet, "No progress bar");
  cmd->add_flag("!--no-plots", options->plots, "Skip the picture");
  cmd->footer(
      "A point that falls is a result. Interrupted runs resume: rerun the same command.\n"
      "Exit codes: 0 ok, 2 bad input, 1 other failure.");
  cmd->callback([options] { runSubcommand([&] { runStability(*options); }); });
}

}  // namespace gaitopt::apps
