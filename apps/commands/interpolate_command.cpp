#include "apps/commands/interpolate_command.hpp"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <map>
#include <memory>
#include <set>

#include <fmt/format.h>

#include "apps/command_runner.hpp"
#include "apps/export_warnings.hpp"
#include "apps/output_options.hpp"
#include "config/config_error.hpp"
#include "config/overrides.hpp"
#include "gaits/export/gait_summary.hpp"
#include "io/output/output_folder.hpp"
#include "io/terminal_text.hpp"
#include "library/interpolation.hpp"
#include "library/library_folder.hpp"
#include "library/point_problem.hpp"
#include "ocp/solve/solution_report.hpp"
#include "report/plot_script.hpp"

namespace gaitopt::apps {
namespace {

struct InterpolateOptions {
  std::string library_dir;
  std::array<double, library::kWalkAxes> walk{};
  std::array<bool, library::kWalkAxes> given{};  ///< --speed, --step-length, --slope given
  std::vector<std::string> at;                   ///< KEY=VALUE on the library's config axes
  OutputOptions output;
};

/// The query's value on every config axis: --at KEY=VALUE, or the axis' only value.
/// @throws config::ConfigError naming --at for a text that is no KEY=VALUE, a key the library
///         does not sweep or given twice, a value that is not a number, or a swept key left out.
std::vector<double> configValues(const library::Grid& grid, const std::vector<std::string>& at) {
  const std::vector<config::Override> overrides = config::parseOverrides(at, "--at");
  std::set<std::string> keys;
  for (const config::Override& o : overrides)
    if (!keys.insert(o.key).second)
      throw config::ConfigError("--at", o.key, 0, "given twice: one value per key");
  std::map<std::string, double> given;
  for (const config::Override& o : overrides) {
    const auto& axes = grid.configAxes();
    if (std::none_of(axes.begin(), axes.end(), [&](const auto& a) { return a.key == o.key; }))
      throw config::ConfigError("--at", o.key, 0, "the library has no config axis of that key");
    double v = 0;
    const auto [end, ec] = std::from_chars(o.value.data(), o.value.data() + o.value.size(), v);
    if (ec != std::errc() || end != o.value.data() + o.value.size() || !std::isfinite(v))
      throw config::ConfigError("--at", o.key, 0, "expected a number, got '" + o.value + "'");
    given[o.key] = v;
  }
  std::vector<double> values;
  for (const auto& axis : grid.configAxes()) {
    if (given.count(axis.key) == 0 && axis.values.size() > 1)
      throw config::ConfigError("--at", axis.key, 0,
                                "the library sweeps this key: give --at " + axis.key + "=VALUE");
    values.push_back(given.count(axis.key) ? given[axis.key] : axis.values.front());
  }
  return values;
}

/// A torque a passive joint may carry before the blend counts as loading it: a millinewton
/// metre, far above the inverse dynamics' rounding (1e-14 N m on the solved gaits) [N m].
constexpr double kUnactuatedTorque = 1e-3;
/// The five-link blends, whose steps end in the double support, close to 1e-11 [-].
constexpr double kBlendPeriodicity = 1e-6;

/// The largest torque the blend asks of a joint without an actuator [N m] (0 when all have one).
double unactuatedTorque(const gaits::Trajectory& traj, const dynamics::Model& model) {
  double largest = 0;
  for (const gaits::Knot& k : traj.knots())
    for (int j = 0; j < model.nLinks(); ++j)
      if (!model.joints()[static_cast<std::size_t>(j)].actuated)
        largest = std::max(largest, std::abs(k.tau(j)));
  return largest;
}

/// A blend of corners that end their steps in an impact (a single-impact gait: the impact map is
/// not linear in the state) neither closes on itself nor keeps a passive joint passive: the
/// torques recomputed from the blended motion then load that joint (RABBIT's ankle, 3 N m).
void warnOfABlendThatIsNoGait(const nlohmann::ordered_json& summary) {
  const double torque = summary["unactuated_torque_Nm"].get<double>();
  const double periodicity = summary["periodicity_error"].get<double>();
  if (torque > kUnactuatedTorque)
    fmt::print(stderr,
               "interpolate: warning: the blend needs {:.3g} N m at a joint without an actuator: "
               "it is no gait of this robot; solve the point instead\n",
               torque);
  if (periodicity > kBlendPeriodicity)
    fmt::print(stderr,
               "interpolate: warning: the blended step does not close on itself (periodicity "
               "error {:.3g}): its corners end in an impact, which a blend does not keep; solve "
               "the point instead\n",
               periodicity);
}

/// The point asked for, by axis: the walk's and each config key's (--at, or its one value).
nlohmann::ordered_json queryJson(const library::Grid& grid, const std::vector<double>& values) {
  nlohmann::ordered_json q = {{"speed", values[library::kSpeed]},
                              {"step_length", values[library::kStepLength]},
                              {"slope", values[library::kSlope]}};
  for (std::size_t a = 0; a < grid.configAxes().size(); ++a)
    q[grid.configAxes()[a].key] = values[library::kWalkAxes + a];
  return q;
}

/// As a config axis of one value may be left out (configValues), so may a walk axis of one
/// value; a slope left out is the library's one, or its base problem's.
/// @throws config::ConfigError naming the option of a walk axis of several values left out.
void fillWalkValues(const library::LibraryFolder& lib, InterpolateOptions& o) {
  const std::array<const char*, library::kWalkAxes> option = {"--speed", "--step-length",
                                                              "--slope"};
  for (int a = 0; a < library::kWalkAxes; ++a) {
    const std::vector<double>& axis = lib.grid.axes()[a];
    if (o.given[a]) continue;
    if (axis.size() == 1)
      o.walk[a] = axis.front();
    else if (a == library::kSlope)
      o.walk[a] = library::basePoint(lib.base)[a];
    else
      throw config::ConfigError(option[a], "", 0,
                                fmt::format("the library has {} values of it, from {:g} to {:g}: "
                                            "give the query's",
                                            axis.size(), axis.front(), axis.back()));
  }
}

void runInterpolate(InterpolateOptions o) {
  io::refuseInputs(o.output.out_dir, {o.library_dir}, "--out");  // before reading it
  const library::LibraryFolder lib = library::readLibraryFolder(o.library_dir);
  std::vector<std::string> inputs = ocp::ocpInputs(lib.base);
  inputs.push_back(o.library_dir);
  const io::OutputFolder out(o.output.out_dir, inputs, "--out", "gait");
  fillWalkValues(lib, o);
  std::vector<double> values(o.walk.begin(), o.walk.end());
  const std::vector<double> keyed = configValues(lib.grid, o.at);
  values.insert(values.end(), keyed.begin(), keyed.end());
  // The model depends on the walk's axes only (config axes are numbers of the OCP file).
  const dynamics::Model model = library::pointProblem(lib.base, o.walk).model;
  library::FolderGaits solved(o.library_dir, lib.grid, model);
  const gaits::Trajectory traj =
      library::interpolateGait(lib.grid, solved.lookup(), model, values, o.output.rate_hz);
  auto summary = gaits::gaitSummary(traj, model, {o.library_dir, "interpolated", 0, 0, 0});
  summary["unactuated_torque_Nm"] = unactuatedTorque(traj, model);
  // The export contract, judged as optimize and poly judge theirs: a blend of angles keeps no
  // contact by construction (the double support's pinned tip, for one, moves).
  summary["between_nodes"] = ocp::betweenNodeMetrics(traj, model, o.output.rate_hz);
  summary["query"] = queryJson(lib.grid, values);
  auto& corners = summary["library_corners"] = nlohmann::ordered_json::array();
  for (const auto& [p, w] : library::cellWeights(lib.grid, values))
    corners.push_back({{"point", lib.grid.point(p).name}, {"weight", w}});
  out.write([&](const std::string& dir) {
    ocp::writeGaitFiles(dir, traj, model, o.output.rate_hz, summary,
                        report::gaitPictures(o.output.plots));
  });
  fmt::print(
      "interpolate: {}; max dynamics residual {:.3g} N m, periodicity error "
      "{:.3g}; wrote {}/trajectory.csv\n",
      io::counted(corners.size(), "corner"), summary["max_defect"].get<double>(),
      summary["periodicity_error"].get<double>(), out.path());
  warnOfABlendThatIsNoGait(summary);
  warnOfBreaches("interpolate", summary["between_nodes"]);
}

}  // namespace

void registerInterpolateCommand(CLI::App& app) {
  auto o = std::make_shared<InterpolateOptions>();
  CLI::App* cmd = app.add_subcommand(
      "interpolate", "The gait between the points of a library, blended from its solved gaits");
  cmd->add_option("--library", o->library_dir, "Library folder (from gaitopt library)")
      ->required()
      ->option_text("DIR");
  CLI::Option* speed =
      cmd->add_option("--speed", o->walk[library::kSpeed],
                      "Walking speed [m/s] (may be left out when the library has one)")
          ->check(CLI::Range(1e-3, 20.0));
  CLI::Option* step = cmd->add_option("--step-length", o->walk[library::kStepLength],
                                      "Step length [m] (may be left out when the library has one)")
                          ->check(CLI::Range(1e-3, 10.0));
  CLI::Option* slope =
      cmd->add_option(
             "--slope", o->walk[library::kSlope],
             "Ground slope [rad], > 0 uphill (default: the library's one slope, or its base "
             "problem's)")
          ->check(CLI::Range(-0.35, 0.35));
  cmd->add_option("--at", o->at,
                  "The query's value of a config key the library sweeps, e.g. --at "
                  "constraints.friction_margin=0.15 (repeatable; a key of one value may be left "
                  "out)")
      ->option_text("KEY=VALUE");
  addOutputOptions(cmd, o->output);
  cmd->footer(
      "Exit codes: 0 ok, 2 bad input, 3 outside the library's grid or a corner not "
      "solved, 1 other failure.");
  cmd->callback([o, speed, step, slope] {
    o->given = {speed->count() > 0, step->count() > 0, slope->count() > 0};
    runSubcommand([&] { runInterpolate(*o); });
  });
}

}  // namespace gaitopt::apps
