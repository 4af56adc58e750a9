#include "apps/interpolate_command.hpp"

#include <filesystem>
#include <map>
#include <memory>

#include <fmt/format.h>

#include "apps/command_runner.hpp"
#include "apps/output_options.hpp"
#include "apps/plotting.hpp"
#include "config/config_error.hpp"
#include "gaits/gait_summary.hpp"
#include "gaits/trajectory_csv.hpp"
#include "io/output_folder.hpp"
#include "io/strict_json.hpp"
#include "library/interpolation.hpp"
#include "library/point_problem.hpp"
#include "ocp/solution_report.hpp"

namespace gaitopt::apps {
namespace {

struct InterpolateOptions {
  std::string library_dir;
  std::array<double, 3> values{};
  bool has_slope = false;
  OutputOptions output;
};

/// The grid and base problem a library folder was built from (its library.json).
struct LibraryFolder {
  library::Grid grid;
  ocp::OcpConfig base;
};

LibraryFolder readLibraryFolder(const std::string& dir) {
  const std::string path = dir + "/library.json";
  if (!std::filesystem::is_regular_file(path))
    throw config::ConfigError(path, "", 0, "not a gait library folder (no library.json)");
  const auto j = io::readStrictJson(path);
  if (!j.is_object() || !j.contains("axes") || !j.contains("ocp"))
    throw config::ConfigError(path, "", 0, "not a library.json written by gaitopt library");
  std::array<std::vector<double>, 3> axes;
  for (int a = 0; a < 3; ++a)
    axes[a] = j.at("axes").at(library::kAxisNames[a]).get<std::vector<double>>();
  // The OCP path is relative to the library folder (library_command.cpp).
  const auto ocp_path = std::filesystem::path(dir) / j.at("ocp").get<std::string>();
  return {library::Grid(axes), ocp::loadOcpConfig(ocp_path.string())};
}

void runInterpolate(InterpolateOptions o) {
  const io::OutputFolder out(o.output.out_dir, {o.library_dir});
  const LibraryFolder lib = readLibraryFolder(o.library_dir);
  if (!o.has_slope) o.values[library::kSlope] = library::basePoint(lib.base)[library::kSlope];
  const dynamics::Model model = library::pointProblem(lib.base, o.values).model;
  std::map<int, std::unique_ptr<gaits::Trajectory>> cache;
  const library::GaitLookup lookup = [&](int p) -> const gaits::Trajectory* {
    auto& slot = cache[p];
    const std::string csv = o.library_dir + "/points/" + lib.grid.point(p).name + "/trajectory.csv";
    if (!slot && std::filesystem::exists(csv))
      slot = std::make_unique<gaits::Trajectory>(gaits::readTrajectoryCsv(csv, model));
    return slot.get();
  };
  const gaits::Trajectory traj =
      library::interpolateGait(lib.grid, lookup, model, o.values, o.output.rate_hz);
  auto summary = gaits::gaitSummary(traj, model, {o.library_dir, "interpolated", 0, 0, 0});
  auto& corners = summary["library_corners"] = nlohmann::ordered_json::array();
  for (const auto& [p, w] : library::cellWeights(lib.grid, o.values))
    corners.push_back({{"point", lib.grid.point(p).name}, {"weight", w}});
  out.write([&](const std::string& dir) {
    ocp::writeGaitFiles(dir, traj, model, summary, gaitPictures(o.output.plots));
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
