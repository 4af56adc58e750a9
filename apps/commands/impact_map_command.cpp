#include "apps/commands/impact_map_command.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include <fmt/format.h>

#include "apps/command_runner.hpp"
#include "apps/option_checks.hpp"
#include "apps/shipped_file.hpp"
#include "config/config_error.hpp"
#include "dynamics/robot_files/robot_config.hpp"
#include "gaits/export/gait_summary.hpp"
#include "gaits/impact/grid_range.hpp"
#include "gaits/impact/impact_map_report.hpp"
#include "io/output/output_folder.hpp"
#include "parallel/progress_bar.hpp"
#include "report/plot_script.hpp"

namespace gaitopt::apps {
namespace {

gaits::ImpactGrid parseGrid(const ImpactMapOptions& o, const dynamics::Model& model) {
  gaits::ImpactGrid grid;
  grid.axes = {gaits::parseRange(o.step_lengths, "--step-lengths", 1.0),
               gaits::parseRange(o.knee_bias, "--knee-bias", kDeg),
               gaits::parseRange(o.approach_angles, "--approach-angles", kDeg)};
  grid.approach_speed = o.approach_speed;
  if (model.legLinks() != 2)
    throw config::ConfigError(o.robot_path, "links", 0,
                              fmt::format("impact-map (Mu ch. 5) needs legs of thigh and shank; "
                                          "robot '{}' has {} link(s) per leg",
                                          model.name(), model.legLinks()));
  // Measured: 705 B of memory per point (the points and their CSV row); rounded up.
  requireGridFits(static_cast<double>(grid.axes[0].count) * grid.axes[1].count * grid.axes[2].count,
                  1024, "command line (--step-lengths x --knee-bias x --approach-angles)");
  try {
    gaits::checkImpactGrid(model, grid, {"--step-lengths", "--knee-bias", "--approach-angles"});
  } catch (const std::invalid_argument& e) {
    throw config::ConfigError("command line", "", 0, e.what());
  }
  return grid;
}

void printResult(const nlohmann::ordered_json& summary) {
  const auto& c = summary["counts"];
  fmt::print("impact-map: single {}, double {}, either {}, neither {} of {} points\n",
             c["single"].get<long>(), c["double"].get<long>(), c["either"].get<long>(),
             c["neither"].get<long>(), summary["points"].get<long>());
  const auto& ref = summary["reference"];
  bool changes_any = false;
  for (const auto& [axis, changes] : ref["changes"].items()) changes_any |= !changes.empty();
  fmt::print("impact-map: through {} ({}){}\n", ref["through"].dump(),
             ref["type"].get<std::string>(),
             changes_any ? ":" : ": the type does not change along the axes through it");
  for (const auto& [axis, changes] : ref["changes"].items())
    for (const auto& ch : changes)
      fmt::print("  along {}: {} -> {} at {:.4g}\n", axis, ch["from"].get<std::string>(),
                 ch["to"].get<std::string>(), ch["at"].get<double>());
}

}  // namespace

void runImpactMap(const ImpactMapOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  const io::OutputFolder out(options.out_dir, {options.robot_path}, "--out", "impact map");
  const dynamics::Model model = dynamics::loadRobot(options.robot_path);
  const gaits::ImpactGrid grid = parseGrid(options, model);
  const int jobs =
      static_cast<int>(std::min<std::size_t>(parallel::resolveJobs(options.jobs), grid.size()));
  fmt::print("impact-map: {} on {} points with {} job(s)\n", model.name(), grid.size(), jobs);
  std::fflush(stdout);
  const gaits::ImpactMap map =
      gaits::sweepImpactMap(model, grid, jobs, parallel::progressBar("impact-map", options.quiet));
  const double elapsed =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  auto summary = gaits::impactMapSummary(map, model);
  summary["jobs"] = jobs;
  summary["wall_time_s"] = elapsed;
  out.write([&](const std::string& dir) {
    gaits::writeImpactMapCsv(map, dir + "/impact_map.csv");
    gaits::writeJsonFile(summary, dir + "/summary.json");
  });
  printResult(summary);
  if (options.plots) {
    report::runPlotScript("impact_map.py", {out.path()}, report::scriptOutput(options.quiet));
    io::listAddedFiles(out.path());  // the pictures: a rerun may replace them
  }
  fmt::print("impact-map: wrote {}/impact_map.csv and summary.json in {:.2f} s\n", out.path(),
             elapsed);
}

void registerImpactMapCommand(CLI::App& app) {
  auto options = std::make_shared<ImpactMapOptions>();
  CLI::App* cmd =
      app.add_subcommand("impact-map",
                         "Map single/double impact over step length, knee bias and approach angle "
                         "(Mu 2004 ch. 5)");
  cmd->add_option("--robot", options->robot_path, "Robot YAML (configs/robots/*.yaml)")
      ->required()
      ->transform(orShippedFile())
      ->option_text("FILE");
  cmd->add_option("--out", options->out_dir, "Result folder (created)")
      ->required()
      ->option_text("DIR");
  cmd->add_option("--step-lengths", options->step_lengths,
                  "Tip distance at touchdown [m] (Mu's S_L / 2), a:b:n or a")
      ->capture_default_str();
  cmd->add_option("--knee-bias", options->knee_bias,
                  "Stance knee bias sigma = theta1 - theta2 [deg], in (0, 180)")
      ->capture_default_str();
  cmd->add_option("--approach-angles", options->approach_angles,
                  "Swing-tip velocity angle alpha from the -x axis [deg], in (0, 180)")
      ->capture_default_str();
  cmd->add_option(
         "--approach-speed", options->approach_speed,
         "Swing-tip speed V_e [m/s]: the impact is linear in it, so it scales the impulses and the "
         "post-impact rates, never which impact occurs")
      ->check(CLI::Range(1e-3, 100.0))
      ->capture_default_str();
  cmd->add_option("--jobs", options->jobs, "Worker threads (default: all cores)")
      ->check(CLI::Range(1, 1024));
  cmd->add_flag("--quiet", options->quiet, "No progress bar");
  cmd->add_flag("!--no-plots", options->plots, "Skip the picture");
  cmd->footer("Exit codes: 0 ok, 2 bad robot file, range or usage, 1 other failure.");
  cmd->callback([options] { runSubcommand([&] { runImpactMap(*options); }); });
}

}  // namespace gaitopt::apps
