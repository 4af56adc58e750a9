#include "apps/study_commands/stability_command.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <stdexcept>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "apps/command_runner.hpp"
#include "apps/option_checks.hpp"
#include "config/config_error.hpp"
#include "gaits/export/gait_summary.hpp"
#include "gaits/impact/grid_range.hpp"
#include "io/output/output_folder.hpp"
#include "io/settings_record.hpp"
#include "parallel/progress_bar.hpp"
#include "report/plot_script.hpp"
#include "sim/scenario/reference_folder.hpp"
#include "sim/studies/map_study.hpp"
#include "sim/studies/sweep_study.hpp"

namespace gaitopt::apps {
namespace {

/// The file of a sweep folder that records what its rows belong to (sim/studies/sweep_study.hpp).
constexpr const char* kSettingsFile = "settings.json";

/// A point's job and its row kept in memory (map node, key, failure text): a few hundred bytes,
/// rounded up.
constexpr double kBytesPerPoint = 512;

struct Sweep {
  const sim::SweepParameter* parameter;
  std::vector<double> values;
  std::unique_ptr<sim::SweepFile> file;
};

struct Map {
  sim::MapParameter a, b;
  std::unique_ptr<sim::SweepFile> file;
};

struct Grids {
  std::vector<Sweep> sweeps;
  std::vector<Map> maps;
};

/// The file's rows on this grid, at the grid's values (sim::SweepFile::rowsAt).
std::map<std::string, sim::SweepRow> onGrid(const Sweep& s) {
  return s.file->rowsAt(s.values);
}

std::map<std::string, sim::SweepRow> onGrid(const Map& m) {
  return m.file->rowsAt(m.a.values, m.b.values);
}

/// The parameter `name` and its range ("" or "=a:b:n"), checked against the scenario
/// (stiffness needs a compliant ground); `option` names the flag in errors. A sweep and a map
/// axis share one rule for the range (sim::sweepValues); a map axis also needs `min_values`.
std::pair<const sim::SweepParameter*, std::vector<double>> parseAxis(const std::string& text,
                                                                     const std::string& option,
                                                                     sim::Scenario base,
                                                                     int min_values = 1) {
  const std::size_t eq = text.find('=');
  const std::string name = text.substr(0, eq);
  try {
    const sim::SweepParameter* p = &sim::sweepParameter(name);
    const gaits::GridAxis axis =
        eq == std::string::npos ? gaits::GridAxis{p->first, p->last, p->count}
                                : gaits::parseRange(text.substr(eq + 1), option + " " + name, 1.0);
    if (axis.count < min_values)
      throw std::invalid_argument(
          fmt::format("a map axis needs at least {} values, increasing (a < b, n >= {})",
                      min_values, min_values));
    sim::setSweepValue(base, name, axis.first);
    return {p, sim::sweepValues(*p, axis)};
  } catch (const std::invalid_argument& e) {
    throw config::ConfigError(option, name, 0, e.what());
  }
}

/// The parameter's value at the nominal point (the robot's friction when the scenario keeps it).
double nominalValue(const sim::Scenario& base, const std::string& name,
                    const dynamics::Model& model) {
  const double v = sim::sweepValue(base, name);
  return name == "friction" && !std::isfinite(v) ? model.friction() : v;
}

/// NAME or NAME=a:b:n and the nominal value (its row file is opened by openFiles).
Sweep parseSweep(const std::string& text, const sim::Scenario& base, const dynamics::Model& model) {
  auto [p, values] = parseAxis(text, "--sweep", base);
  return {p, sim::withNominal(std::move(values), nominalValue(base, p->name(), model)), nullptr};
}

/// A[=a:b:n],B[=c:d:m]: two different parameters, each with at least 2 increasing values.
Map parseMap(const std::string& text, const sim::Scenario& base, const dynamics::Model& model) {
  const std::size_t comma = text.find(',');
  if (comma == std::string::npos || text.find(',', comma + 1) != std::string::npos)
    throw config::ConfigError("--map", text, 0, "expected two parameters, A[=a:b:n],B[=c:d:m]");
  Map m;
  for (auto* axis : {&m.a, &m.b}) {
    const std::string part = axis == &m.a ? text.substr(0, comma) : text.substr(comma + 1);
    auto [p, values] = parseAxis(part, "--map", base, 2);
    const double nominal = nominalValue(base, p->name(), model);
    *axis = {p, sim::withNominal(std::move(values), nominal), nominal};
  }
  if (m.a.parameter == m.b.parameter)
    throw config::ConfigError("--map", m.a.parameter->name(), 0,
                              "the same parameter twice; a map varies two different ones");
  return m;
}

/// The grid the folder's rows belong to: with the scenario, it keys the folder (settings.json).
nlohmann::ordered_json gridKey(const Grids& g) {
  nlohmann::ordered_json key = {{"sweeps", nlohmann::ordered_json::array()},
                                {"maps", nlohmann::ordered_json::array()}};
  for (const auto& s : g.sweeps) key["sweeps"].push_back({s.parameter->name(), s.values});
  for (const auto& m : g.maps)
    key["maps"].push_back({m.a.parameter->name(), m.a.values, m.b.parameter->name(), m.b.values});
  return key;
}

/// Each sweep writes its own row file, sweep_NAME.csv: a parameter swept twice would mix two
/// grids in one file. @throws config::ConfigError (exit 2).
void requireDistinct(const std::vector<Sweep>& sweeps) {
  for (std::size_t i = 0; i < sweeps.size(); ++i)
    for (std::size_t k = 0; k < i; ++k)
      if (sweeps[i].parameter == sweeps[k].parameter)
        throw config::ConfigError("--sweep", sweeps[i].parameter->name(), 0,
                                  "the same parameter twice; give one range per parameter");
}

/// Every --sweep and --map, checked before the folder exists (bad input leaves none behind). All
/// their points are planned at once, so the memory budget holds for the sum.
Grids parseGrids(const StabilityOptions& o, const sim::Scenario& base,
                 const dynamics::Model& model) {
  Grids g;
  double points = 0;
  for (const auto& text : o.sweeps) {
    g.sweeps.push_back(parseSweep(text, base, model));
    points += static_cast<double>(g.sweeps.back().values.size());
    requireGridFits(points, kBytesPerPoint, "--sweep " + text);
  }
  for (const auto& text : o.maps) {
    const Map& m = g.maps.emplace_back(parseMap(text, base, model));
    points += static_cast<double>(m.a.values.size()) * static_cast<double>(m.b.values.size());
    requireGridFits(points, kBytesPerPoint, "--map " + text);
  }
  requireDistinct(g.sweeps);
  return g;
}

/// The row files of a folder: sweep_NAME.csv per sweep, map_A_B.csv per map.
std::string fileOf(const Sweep& s) {
  return "sweep_" + s.parameter->name() + ".csv";
}
std::string fileOf(const Map& m) {
  return "map_" + m.a.parameter->name() + "_" + m.b.parameter->name() + ".csv";
}

/// Opens the row files in `out_dir` (rows of an earlier run are read back), once the folder's
/// settings are claimed: a refused run must not touch them (a torn last row is cut).
void openFiles(Grids& grids, const std::string& out_dir) {
  for (auto& s : grids.sweeps) s.file = std::make_unique<sim::SweepFile>(out_dir + "/" + fileOf(s));
  for (auto& m : grids.maps)
    m.file = std::make_unique<sim::SweepFile>(
        out_dir + "/" + fileOf(m),
        std::vector<std::string>{m.a.parameter->name(), m.b.parameter->name()});
}

void printInterval(const std::string& name, const nlohmann::ordered_json& j) {
  if (j["walks_from"].is_null()) {
    fmt::print("stability: {}: no walking interval around the nominal value\n", name);
    return;
  }
  const std::string unit = j["unit"].get<std::string>();
  fmt::print("stability: {}: walks from {:.4g} to {:.4g}{}\n", name, j["walks_from"].get<double>(),
             j["walks_to"].get<double>(), unit.empty() ? "" : " " + unit);
  for (const char* side : {"fails_below", "fails_above"})
    if (j.contains(side))
      fmt::print("  at {:.4g}: {}\n", j[side]["value"].get<double>(),
                 j[side]["failure"].get<std::string>());
}

void printRegion(const std::string& name, const nlohmann::ordered_json& j) {
  fmt::print("stability: map {}: {} of {} points walk{}\n", name, j["points_walked"].get<int>(),
             j["points"].get<int>(), j["nominal_walks"].get<bool>() ? "" : " (not the nominal)");
  const auto& r = j["largest_rectangle_around_nominal"];
  if (!r.is_null())
    fmt::print(
        "  largest walking rectangle around the nominal point: {} {:.4g} .. {:.4g} x {} "
        "{:.4g} .. {:.4g} ({} point{})\n",
        j["a"]["name"].get<std::string>(), r["a_from"].get<double>(), r["a_to"].get<double>(),
        j["b"]["name"].get<std::string>(), r["b_from"].get<double>(), r["b_to"].get<double>(),
        r["points"].get<int>(), r["points"].get<int>() == 1 ? "" : "s");
}

}  // namespace

void runStability(const StabilityOptions& o) {
  if (o.sweeps.empty() && o.maps.empty())
    throw config::ConfigError("--sweep", "", 0, "nothing to do: give --sweep or --map");
  const sim::ReferenceFolder ref = sim::loadReferenceFolder(
      o.scenario.reference_dir, o.scenario.robot_path, sim::robotOverrides(o.scenario));
  sim::requireControllerFits(o.scenario, ref.model);
  const sim::Reference reference(ref.step, ref.model);
  sim::Scenario base = sim::makeScenario(o.scenario);
  base.poincare = o.poincare;
  if (base.poincare && base.ground.getIf<sim::RigidGround>() == nullptr)
    throw config::ConfigError("--poincare", "", 0,
                              fmt::format("the Poincare map is computed on the rigid ground only, "
                                          "not on the {} ground",
                                          sim::groundName(base.ground)));
  checkControllerFitsReference(ref, reference, base);
  Grids grids = parseGrids(o, base, ref.model);
  const io::ResumableFolder folder(o.out_dir, sim::scenarioInputs(o.scenario, ref), kSettingsFile);
  const std::string& out_dir = folder.path();
  nlohmann::ordered_json key = sim::sweepFolderSettings(o.scenario, ref, base);
  key.update(gridKey(grids));
  io::claimSettings(out_dir + "/" + kSettingsFile, key);
  openFiles(grids, out_dir);
  // Each job walks one point and appends its row: on disk as soon as it is done.
  std::vector<std::function<void()>> todo;
  std::size_t done_before = 0;
  for (auto& s : grids.sweeps)
    for (double v : s.values) {
      if (s.file->has(v)) {
        ++done_before;
        continue;
      }
      todo.push_back([&, v] {
        s.file->append(sim::walkSweepPoint(ref.model, reference, base, s.parameter->name(), v));
      });
    }
  for (auto& m : grids.maps)
    for (double va : m.a.values)
      for (double vb : m.b.values) {
        if (m.file->has(va, vb)) {
          ++done_before;
          continue;
        }
        todo.push_back([&, va, vb] {
          m.file->append(sim::walkMapPoint(ref.model, reference, base, m.a.parameter->name(), va,
                                           m.b.parameter->name(), vb));
        });
      }
  // No more workers than points: a sweep of 2 points starts 2 threads, not one per core.
  const int jobs = static_cast<int>(
      std::min<std::size_t>(parallel::resolveJobs(o.jobs), std::max<std::size_t>(todo.size(), 1)));
  fmt::print("stability: {} points to walk ({} done before) with {} job(s)\n", todo.size(),
             done_before, jobs);
  std::fflush(stdout);
  parallel::parallelFor(
      todo.size(), jobs, [&](std::size_t i) { todo[i](); },
      parallel::progressBar("stability", o.quiet));
  nlohmann::ordered_json summary{{"robot", ref.model.name()}, {"robot_file", ref.robot_path}};
  summary.update(sim::scenarioJson(o.scenario, base));
  // What else shapes every row, recorded as simulate records it: the nominal plant's friction
  // (--friction, --set robot.friction or the robot's; a sweep at friction 0.3 fell for a reason
  // the summary did not give), foot and slope, and whether Poincare maps were taken.
  const dynamics::Model plant = sim::scenarioPlant(ref.model, base);
  summary["slope_rad"] = plant.slope();
  summary["friction"] = plant.friction();
  summary["foot"] = gaits::footJson(plant.foot());
  summary["poincare"] = base.poincare;
  for (const auto& s : grids.sweeps) {
    const std::string name = s.parameter->name();
    summary["sweeps"][name] =
        sim::walkingInterval(*s.parameter, onGrid(s), nominalValue(base, name, ref.model));
    printInterval(name, summary["sweeps"][name]);
  }
  for (const auto& m : grids.maps) {
    const std::string name = m.a.parameter->name() + "_" + m.b.parameter->name();
    summary["maps"][name] = sim::walkingRegion(m.a, m.b, onGrid(m));
    printRegion(name, summary["maps"][name]);
  }
  gaits::writeJsonFile(summary, out_dir + "/summary.json");
  if (o.plots)
    report::runPlotScript("stability_plots.py", {out_dir}, report::scriptOutput(o.quiet));
  std::vector<std::string> files{"summary.json"};
  for (const auto& s : grids.sweeps) files.push_back(fileOf(s));
  for (const auto& m : grids.maps) files.push_back(fileOf(m));
  fmt::print("stability: wrote {}/{}\n", out_dir, fmt::join(files, ", "));
}

void registerStabilityCommand(CLI::App& app) {
  auto options = std::make_shared<StabilityOptions>();
  CLI::App* cmd = app.add_subcommand(
      "stability",
      "Sweep push, model error, friction, ground stiffness or gains, or map two of them: where "
      "walking stops");
  addScenarioOptions(cmd, options->scenario);
  std::string names;
  for (const auto& p : sim::sweepParameters())
    names += fmt::format("\n  {}{}: {} (default {}:{}:{}{})", p.name(),
                         p.unit().empty() ? "" : " [" + p.unit() + "]", p.meaning, p.first, p.last,
                         p.count, p.geometric ? ", geometric spacing" : "");
  // The nominal is the base scenario's value (--push 1 --sweep push
  // grows its interval from 1, not 0): said where the sweep is asked for.
  cmd->add_option("--sweep", options->sweeps,
                  "NAME or NAME=a:b:n (n values, a < b; n = 1: the value a), repeatable. The "
                  "nominal value, always walked and the centre of the walking interval, is the "
                  "scenario's own: --push, --mass-error and --length-error (else the uncertainty "
                  "case's errors), --gain-scale, --friction (else the robot's), the ground's "
                  "stiffness. NAME:" +
                      names)
      ->option_text("NAME[=a:b:n]");
  cmd->add_option(
         "--map", options->maps,
         "A 2-D map over two different parameters, A varied slowest (rows), each point "
         "a walk; ranges as --sweep with n >= 2 (e.g. push=-3:3:25,mass_error=-0.2:0.2:17);"
         " writes map_A_B.csv and map_A_B.png. Repeatable")
      ->option_text("A[=a:b:n],B[=c:d:m]");
  cmd->add_option("--out", options->out_dir, "Result folder (created; reruns resume in it)")
      ->required()
      ->option_text("DIR");
  cmd->add_option("--jobs", options->jobs, "Worker threads (default: all cores)")
      ->check(CLI::Range(1, 1024));
  cmd->add_flag("--poincare", options->poincare,
                "Also the Poincare multipliers of every point (rigid ground; about 4 n + 18 steps "
                "more for n links, more with a controller memory)");
  cmd->add_flag("--quiet", options->quiet, "No progress bar");
  cmd->add_flag("!--no-plots", options->plots, "Skip the picture");
  cmd->footer(
      "A point that falls is a result. Interrupted runs resume: rerun the same command.\n"
      "Exit codes: 0 ok, 2 bad input, 1 other failure.");
  cmd->callback([options] { runSubcommand([&] { runStability(*options); }); });
}

}  // namespace gaitopt::apps
