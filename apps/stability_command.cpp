#include "apps/stability_command.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>

#include <fmt/format.h>

#include "apps/command_runner.hpp"
#include "apps/plotting.hpp"
#include "apps/progress_bar.hpp"
#include "apps/range_option.hpp"
#include "apps/reference_folder.hpp"
#include "apps/sweep_file.hpp"
#include "config/config_error.hpp"
#include "gaits/gait_summary.hpp"
#include "io/output_folder.hpp"
#include "io/settings_record.hpp"

namespace gaitopt::apps {
namespace {

struct Sweep {
  const sim::SweepParameter* parameter;
  std::vector<double> values;
  std::unique_ptr<SweepFile> file;
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
                                   : parseRange(text.substr(eq + 1), "--sweep " + name, 1.0);
  try {
    sim::setSweepValue(base, name, axis.first);
  } catch (const std::invalid_argument& e) {
    throw config::ConfigError("--sweep", name, 0, e.what());
  }
  Sweep s{p, {}, std::make_unique<SweepFile>(out_dir + "/sweep_" + name + ".csv")};
  if (p->geometric && !(axis.first > 0 && axis.last > 0))
    throw config::ConfigError("--sweep", name, 0, "a geometric range needs positive ends");
  for (int k = 0; k < axis.count; ++k) {
    const double v = !p->geometric || axis.count == 1
                         ? axis.value(k)
                         : axis.first * std::pow(axis.last / axis.first,
                                                 static_cast<double>(k) / (axis.count - 1));
    // Rounding noise snapped to 0, so -0.3:0.5:17 holds 0 rather than 5.6e-17.
    const double scale = std::max(std::abs(axis.first), std::abs(axis.last));
    s.values.push_back(std::abs(v) < 1e-12 * scale ? 0.0 : v);
  }
  return s;
}

SweepRow walkPoint(const ReferenceFolder& ref, const sim::Reference& reference,
                   sim::Scenario scenario, const std::string& name, double value) {
  sim::setSweepValue(scenario, name, value);
  const sim::ScenarioResult r = sim::runScenario(ref.model, reference, scenario);
  SweepRow row{value,       r.walk.steps_completed, scenario.steps,
               r.walk.fell, r.walk.failure,         r.walk.max_tracking_error};
  if (r.poincare && r.poincare->ok) row.max_multiplier = r.poincare->max_multiplier;
  if (r.walk.steps_completed > 0)
    row.mean_advance = sim::completedTotals(r.walk).distance / r.walk.steps_completed;
  row.wall_time_s = r.wall_time_s;
  return row;
}

/// The interval of values around the nominal one where every point walks all its steps.
nlohmann::ordered_json walkingInterval(const Sweep& s, double nominal) {
  std::vector<SweepRow> rows;
  for (const auto& [k, row] : s.file->rows()) rows.push_back(row);
  std::sort(rows.begin(), rows.end(),
            [](const SweepRow& a, const SweepRow& b) { return a.value < b.value; });
  const auto walks = [](const SweepRow& r) {
    return !r.fell && r.steps_completed == r.steps_requested;
  };
  nlohmann::ordered_json j{{"unit", s.parameter->unit},
                           {"meaning", s.parameter->meaning},
                           {"values", rows.size()},
                           {"nominal", std::isfinite(nominal) ? nlohmann::ordered_json(nominal)
                                                              : nlohmann::ordered_json()},
                           {"walks_from", nullptr},
                           {"walks_to", nullptr}};
  if (rows.empty() || !std::isfinite(nominal)) return j;
  std::size_t c = 0;  // the point nearest the nominal value
  for (std::size_t i = 1; i < rows.size(); ++i)
    if (std::abs(rows[i].value - nominal) < std::abs(rows[c].value - nominal)) c = i;
  if (!walks(rows[c])) return j;
  std::size_t lo = c, hi = c;
  while (lo > 0 && walks(rows[lo - 1])) --lo;
  while (hi + 1 < rows.size() && walks(rows[hi + 1])) ++hi;
  j["walks_from"] = rows[lo].value;
  j["walks_to"] = rows[hi].value;
  if (lo > 0) j["fails_below"] = {{"value", rows[lo - 1].value}, {"failure", rows[lo - 1].failure}};
  if (hi + 1 < rows.size())
    j["fails_above"] = {{"value", rows[hi + 1].value}, {"failure", rows[hi + 1].failure}};
  return j;
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

/// What defines a sweep folder's rows: a rerun under other settings would mix two experiments.
nlohmann::ordered_json sweepSettings(const StabilityOptions& o, const ReferenceFolder& ref,
                                     const sim::Scenario& base) {
  const ScenarioOptions& s = o.scenario;
  return {{"robot", ref.model.name()},
          {"robot_file_fnv1a", io::fileFingerprint(ref.robot_path)},
          {"reference_trajectory_fnv1a", io::fileFingerprint(ref.dir + "/trajectory.csv")},
          {"controller", s.controller},
          {"gain_scale", s.gain_scale},
          {"ground_file_fnv1a", io::fileFingerprint(groundPath(s.ground))},
          {"uncertainty_case", s.uncertainty_case},
          {"uncertainty_on", s.uncertainty_on},
          {"friction", s.friction},
          {"push_impulse_Ns", s.push},
          {"steps", base.steps},
          {"poincare", o.poincare}};
}

}  // namespace

void runStability(const StabilityOptions& o) {
  const ReferenceFolder ref = loadReferenceFolder(o.scenario.reference_dir, o.scenario.robot_path);
  requireControllerFits(o.scenario, ref.model);
  const sim::Reference reference(ref.step);
  sim::Scenario base = makeScenario(o.scenario);
  base.poincare = o.poincare;
  const io::ResumableFolder folder(o.out_dir, scenarioInputs(o.scenario));
  const std::string& out_dir = folder.path();
  io::claimSettings(out_dir + "/settings.json", sweepSettings(o, ref, base));
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
        p.sweep->file->append(walkPoint(ref, reference, base, p.sweep->parameter->name, p.value));
      },
      progressBar("stability", o.quiet));
  nlohmann::ordered_json summary{{"robot", ref.model.name()}};
  summary.update(scenarioJson(o.scenario, base));
  for (const auto& s : sweeps) {
    double nominal = sim::sweepValue(base, s.parameter->name);
    if (s.parameter->name == "friction" && !std::isfinite(nominal)) nominal = ref.model.friction();
    summary["sweeps"][s.parameter->name] = walkingInterval(s, nominal);
    printInterval(s.parameter->name, summary["sweeps"][s.parameter->name]);
  }
  gaits::writeJsonFile(summary, out_dir + "/summary.json");
  if (o.plots) runPlotScript("stability_plots.py", {out_dir});
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
