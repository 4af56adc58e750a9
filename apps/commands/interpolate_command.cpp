#include "apps/commands/interpolate_command.hpp"

#include <array>
#include <memory>

#include <fmt/format.h>

#include "apps/command_runner.hpp"
#include "apps/output_options.hpp"
#include "gaits/export/gait_summary.hpp"
#include "io/output/output_folder.hpp"
#include "library/interpolation.hpp"
#include "library/library_folder.hpp"
#include "library/point_problem.hpp"
#include "ocp/solve/solution_report.hpp"
#include "report/plot_script.hpp"

namespace gaitopt::apps {
namespace {

struct InterpolateOptions {
  std::string library_dir;
  std::array<double, 3> values{};
  bool has_slope = false;
  OutputOptions output;
};

void runInterpolate(InterpolateOptions o) {
  io::refuseInputs(o.output.out_dir, {o.library_dir}, "--out");  // before reading it
  const library::LibraryFolder lib = library::readLibraryFolder(o.library_dir);
  std::vector<std::string> inputs = ocp::ocpInputs(lib.base);
  inputs.push_back(o.library_dir);
  const io::OutputFolder out(o.output.out_dir, inputs);
  if (!o.has_slope) o.values[library::kSlope] = library::basePoint(lib.base)[library::kSlope];
  const dynamics::Model model = library::pointProblem(lib.base, o.values).model;
  library::FolderGaits solved(o.library_dir, lib.grid, model);
  const gaits::Trajectory traj =
      library::interpolateGait(lib.grid, solved.lookup(), model, o.values, o.output.rate_hz);
  auto summary = gaits::gaitSummary(traj, model, {o.library_dir, "interpolated", 0, 0, 0});
  auto& corners = summary["library_corners"] = nlohmann::ordered_json::array();
  for (const auto& [p, w] : library::cellWeights(lib.grid, o.values))
    corners.push_back({{"point", lib.grid.point(p).name}, {"weight", w}});
  out.write([&](const std::string& dir) {
    ocp::writeGaitFiles(dir, traj, model, o.output.rate_hz, summary,
                        report::gaitPictures(o.output.plots));
  });
  fmt::print(
      "interpolate: {} corners; max dynamics residual {:.3g} N m, periodicity error "
      "{:.3g}; wrote {}/trajectory.csv\n",
      corners.size(), summary["max_defect"].get<double>(),
      summary["periodicity_error"].get<double>(), out.path());
}

}  // namespace

void registerInterpolateCommand(CLI::App& app) {
  auto o = std::make_shared<InterpolateOptions>();
  CLI::App* cmd = app.add_subcommand(
      "interpolate", "The gait between the points of a library, blended from its solved gaits");
  cmd->add_option("--library", o->library_dir, "Library folder (from gaitopt library)")
      ->required()
      ->option_text("DIR");
  cmd->add_option("--speed", o->values[library::kSpeed], "Walking speed [m/s]")
      ->required()
      ->check(CLI::Range(1e-3, 20.0));
  cmd->add_option("--step-length", o->values[library::kStepLength], "Step length [m]")
      ->required()
      ->check(CLI::Range(1e-3, 10.0));
  CLI::Option* slope =
      cmd->add_option("--slope", o->values[library::kSlope],
                      "Ground slope [rad], > 0 uphill (default: the library's base slope)")
          ->check(CLI::Range(-0.35, 0.35));
  addOutputOptions(cmd, o->output);
  cmd->footer(
      "Exit codes: 0 ok, 2 bad input, 3 outside the library's grid or a corner not "
      "solved, 1 other failure.");
  cmd->callback([o, slope] {
    o->has_slope = slope->count() > 0;
    runSubcommand([&] { runInterpolate(*o); });
  });
}

}  // namespace gaitopt::apps
