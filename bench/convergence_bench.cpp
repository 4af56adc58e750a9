/// @file convergence_bench.cpp
/// How often the shipped problems converge, and to which optimum: every OCP
/// config at SSP meshes of 24, 27, 30, 33 and 36 segments, each from two starts, the config's
/// own initial guess (the polynomial gait, or the straight-leg guess) and a neighbouring solved
/// gait (the config's solution at its shipped mesh, resampled onto the other mesh and re-solved
/// with Ipopt's warm start, as `gaitopt optimize --warm-start` re-solves it), plus every
/// point of the shipped gait libraries from the polynomial gait, and each point that fails so
/// again from a converged neighbour, as `gaitopt library` starts it. One solve is one draw: the
/// success rate over the draws and the spread of the converged costs per config are what a
/// user who changes the mesh or the start meets.
/// Writes one CSV row per solve and prints a markdown table per config.
/// Usage: convergence_bench OUT.csv [OCP_CONFIG | LIBRARY_CONFIG ...]
///        (default: every configs/ocp/*.yaml and configs/library/*.yaml of the source tree)
///        convergence_bench --table CSV   (the table of an earlier run)
#include <algorithm>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <unistd.h>

#include <fmt/format.h>

#include "io/output/checked_write.hpp"
#include "library/grid.hpp"
#include "library/library_config.hpp"
#include "library/library_point.hpp"
#include "ocp/guess/initial_guess.hpp"
#include "ocp/solve/gait_solve.hpp"
#include "ocp_bench_common.hpp"

namespace gaitopt::bench {
namespace {

namespace fs = std::filesystem;

constexpr int kMeshes[] = {24, 27, 30, 33, 36};
/// Appended to a library's name for the draws that retry its failed points from a neighbour.
constexpr std::string_view kRetrySuffix = " (neighbour start)";

/// One solve: the config, its SSP mesh, where it started, and how it ended.
struct Draw {
  std::string config, start;
  int segments = 0;
  std::string status;
  bool converged = false;
  int iterations = 0;
  double cost = 0, wall_s = 0;
};

Draw drawOf(const std::string& name, int segments, const std::string& start,
            const ocp::SolveResult& r) {
  return {name, start, segments, r.status, r.success, r.iterations, r.cost, r.wall_time_s};
}

/// The config at an SSP mesh of `segments` equal segments (mesh refinement left as configured).
ocp::OcpConfig atMesh(ocp::OcpConfig config, int segments) {
  config.phases.front().segments = segments;
  config.phases.front().clearMesh();
  config.solver.progress = false;
  return config;
}

/// Solves `config` from `guess`, or a row "error" when it cannot even be set up.
Draw solve(const std::string& name, const dynamics::Model& model, const ocp::OcpConfig& config,
           const gaits::Trajectory& guess, const std::string& start,
           std::optional<ocp::GaitSolution>* kept = nullptr) {
  const int segments = config.phases.front().segments;
  try {
    ocp::GaitSolution s = ocp::solveGait(model, config, guess);
    Draw d = drawOf(name, segments, start, s.result);
    if (kept != nullptr) *kept = std::move(s);
    return d;
  } catch (const std::exception& e) {
    return {name, start, segments, std::string("error: ") + e.what(), false, 0, 0, 0};
  }
}

/// The config's own guess and the neighbour's at every mesh.
std::vector<Draw> ocpDraws(const std::string& path) {
  const std::string name = fs::path(path).stem().string();
  const ocp::OcpConfig shipped = ocp::loadOcpConfig(path);
  const dynamics::Model model = ocp::problemModel(shipped);
  const gaits::Trajectory own = ocp::initialGuess(model, shipped);
  const std::string own_name = shipped.guess_gait_path.empty() ? "straight_leg" : "polynomial";
  // The neighbour: the solution at the shipped mesh (not a draw of its own).
  std::optional<ocp::GaitSolution> neighbour;
  solve(name, model, shipped, own, own_name, &neighbour);
  std::vector<Draw> draws;
  const std::optional<gaits::Trajectory> warm =
      neighbour && neighbour->result.success
          ? std::optional(ocp::reconstructDense(neighbour->problem, model, neighbour->result.x,
                                                ocp::kRefinementResampleHz))
          : std::nullopt;
  for (const int segments : kMeshes) {
    const ocp::OcpConfig config = atMesh(shipped, segments);
    draws.push_back(solve(name, model, config, own, own_name));
    if (!warm) continue;
    ocp::OcpConfig warm_config = config;  // as `gaitopt optimize --warm-start` solves it
    warm_config.solver = ocp::warmStarted(config.solver);
    draws.push_back(solve(name, model, warm_config, *warm, "neighbour (shipped mesh)"));
  }
  return draws;
}

/// A library point's draw: its index row as the bench records it (a point that could not be set
/// up says why, as a config's draw does).
Draw drawOf(const std::string& name, int segments, const library::IndexRow& row) {
  const std::string status = row.status == "error" ? "error: " + row.message : row.status;
  return {name,          row.start,      segments, status,
          row.converged, row.iterations, row.cost, row.solve_time_s};
}

/// Every point of a library from the polynomial gait (no warm start), into a scratch folder,
/// under the library's name, the root (the base problem's point) also along the base config's
/// continuation if that fails, as `gaitopt library` starts its root (the continuation from
/// every point's polynomial gait would take hours on the ensemble library: at 0.3 m/s and 0.3 m
/// it ran 30 min and failed); then, under "NAME (neighbour start)", every point that failed,
/// warm-started from a converged grid neighbour as `gaitopt library` would start it, in passes
/// until none is left to try (a point solved so serves its own neighbours; each failed point
/// is tried once).
std::vector<Draw> libraryDraws(const std::string& path, const std::string& scratch) {
  library::LibraryConfig config = library::loadLibraryConfig(path);
  const std::string name = "library " + fs::path(path).stem().string();
  library::Grid grid(config.axes, config.config_axes);
  const int segments = config.base.phases.front().segments;
  const int root = grid.nearest(library::basePoint(config));
  library::LibrarySetup setup{std::move(config), std::move(grid), scratch, {path, 100, {}, {}, {}}};
  std::vector<Draw> draws;
  std::vector<bool> solved(setup.grid.size()), tried(setup.grid.size());
  for (int p = 0; p < setup.grid.size(); ++p) {
    setup.continuation = p == root;
    const library::IndexRow row = library::solveLibraryPoint(setup, {p, -1});
    draws.push_back(drawOf(name, segments, row));
    solved[p] = row.converged;
  }
  for (bool progress = true; progress;) {
    progress = false;
    for (int p = 0; p < setup.grid.size(); ++p) {
      if (solved[p] || tried[p]) continue;
      const std::vector<int> near = setup.grid.neighbours(p);
      const auto from = std::find_if(near.begin(), near.end(), [&](int q) { return solved[q]; });
      if (from == near.end()) continue;
      setup.continuation = false;
      const library::IndexRow row = library::solveLibraryPoint(setup, {p, *from});
      draws.push_back(drawOf(name + std::string(kRetrySuffix), segments, row));
      tried[p] = progress = true;
      solved[p] = row.converged;
    }
  }
  return draws;
}

std::string csvOf(const std::vector<Draw>& draws) {
  std::string text = "config,ssp_segments,start,status,converged,iterations,cost,wall_s\n";
  auto cell = [](std::string text) {  // a start ("warm:P,polynomial") or status as one cell
    std::replace(text.begin(), text.end(), ',', ';');
    std::replace(text.begin(), text.end(), '\n', ' ');
    return text;
  };
  for (const Draw& d : draws)
    text += fmt::format("{},{},{},{},{},{},{:.10g},{:.4f}\n", d.config, d.segments, cell(d.start),
                        cell(d.status), d.converged ? 1 : 0, d.iterations, d.cost, d.wall_s);
  return text;
}

/// (problems converged, problems). A config's draw is a problem of its own; a library point is
/// one problem however many starts it took: its first draw, and the neighbour-start draw that
/// libraryDraws adds only for a point whose first draw failed (once per point).
std::pair<int, int> problemTally(const std::vector<Draw>& draws) {
  int solved = 0, problems = 0;
  for (const Draw& d : draws) {
    const std::string_view name = d.config;
    const bool is_retry = name.size() > kRetrySuffix.size() &&
                          name.substr(name.size() - kRetrySuffix.size()) == kRetrySuffix;
    problems += is_retry ? 0 : 1;  // a retry is a point already counted by its first draw
    solved += d.converged ? 1 : 0;
  }
  return {solved, problems};
}

/// Per config: draws converged, the converged costs' range and spread, median iterations and
/// time. The spread is (max - min) / min of the converged costs.
void printTable(const std::vector<Draw>& draws) {
  std::map<std::string, std::vector<const Draw*>> by_config;
  for (const Draw& d : draws) by_config[d.config].push_back(&d);
  fmt::print(
      "| config | converged | least cost | greatest cost | spread | median iterations | "
      "median solve s |\n|---|---:|---:|---:|---:|---:|---:|\n");
  int converged = 0;
  for (const auto& [name, group] : by_config) {
    std::vector<double> costs, iterations, times;
    for (const Draw* d : group) {
      iterations.push_back(d->iterations);
      times.push_back(d->wall_s);
      if (d->converged) costs.push_back(d->cost);
    }
    converged += static_cast<int>(costs.size());
    const auto [lo, hi] = std::minmax_element(costs.begin(), costs.end());
    // A library's points are different problems, and a cost near zero (the passive gait) has
    // no relative spread: both say "-".
    const bool spread = !costs.empty() && name.rfind("library ", 0) != 0 && std::abs(*lo) > 1e-6;
    fmt::print("| {} | {} of {} | {} | {} | {} | {:.0f} | {:.3f} |\n", name, costs.size(),
               group.size(), costs.empty() ? "-" : fmt::format("{:.6g}", *lo),
               costs.empty() ? "-" : fmt::format("{:.6g}", *hi),
               spread ? fmt::format("{:.2f} %", 100 * (*hi - *lo) / std::abs(*lo)) : "-",
               median(iterations), median(times));
  }
  fmt::print("\n{} of {} solves converged ({:.1f} %).\n", converged, draws.size(),
             100.0 * converged / static_cast<double>(draws.size()));
  const auto [solved, problems] = problemTally(draws);
  fmt::print(
      "{} of {} problems converged ({:.1f} %): a config at a mesh from a start is one problem, "
      "a library point one problem, solved when its polynomial start or its neighbour start "
      "converged.\n",
      solved, problems, 100.0 * solved / problems);
}

/// The draws of a CSV this program wrote (csvOf). @throws std::runtime_error when unreadable.
std::vector<Draw> readCsv(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error(path + ": cannot read it");
  std::vector<Draw> draws;
  std::string line;
  std::getline(in, line);  // the header
  while (std::getline(in, line)) {
    std::vector<std::string> cell;
    std::stringstream row(line);
    for (std::string c; std::getline(row, c, ',');) cell.push_back(c);
    if (cell.size() != 8) throw std::runtime_error(path + ": not a row of 8 cells: " + line);
    draws.push_back({cell[0], cell[2], std::stoi(cell[1]), cell[3], cell[4] == "1",
                     std::stoi(cell[5]), std::stod(cell[6]), std::stod(cell[7])});
  }
  return draws;
}

std::vector<std::string> shippedConfigs() {
  std::vector<std::string> paths;
  for (const char* folder : {"configs/ocp", "configs/library"})
    for (const auto& entry : fs::directory_iterator(fs::path(GAITOPT_SOURCE_DIR) / folder))
      if (entry.path().extension() == ".yaml") paths.push_back(entry.path().string());
  std::sort(paths.begin(), paths.end());
  return paths;
}

}  // namespace
}  // namespace gaitopt::bench

int main(int argc, char** argv) {
  using namespace gaitopt;
  const bool table = argc == 3 && std::string(argv[1]) == "--table";
  // An option other than --table is a mistake, not an output file: a run takes minutes.
  if (argc < 2 || (!table && argv[1][0] == '-')) {
    std::fprintf(stderr,
                 "usage: %s OUT.csv [OCP_CONFIG | LIBRARY_CONFIG ...]\n       %s --table CSV\n",
                 argv[0], argv[0]);
    return 2;
  }
  if (table) {  // the table of an earlier run's CSV
    bench::printTable(bench::readCsv(argv[2]));
    return 0;
  }
  std::vector<std::string> paths(argv + 2, argv + argc);
  if (paths.empty()) paths = bench::shippedConfigs();
  const auto scratch = std::filesystem::temp_directory_path() /
                       fmt::format("convergence_bench_{}", static_cast<long>(::getpid()));
  std::vector<bench::Draw> draws;
  for (const std::string& path : paths) {
    const bool library = path.find("/library/") != std::string::npos;
    std::fprintf(stderr, "convergence_bench: %s\n", path.c_str());
    const auto more =
        library ? bench::libraryDraws(path, (scratch / "library").string()) : bench::ocpDraws(path);
    draws.insert(draws.end(), more.begin(), more.end());
    io::writeFileAtomically(argv[1], bench::csvOf(draws));  // a long run keeps what it has
  }
  std::filesystem::remove_all(scratch);
  bench::printTable(draws);
  return 0;
}
