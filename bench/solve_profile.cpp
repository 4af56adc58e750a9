/// @file solve_profile.cpp
/// Where the time of a whole gait solve goes, the way `gaitopt optimize` spends it:
/// reading the config and robot, the polynomial guess, building the NLP, recording the
/// sparsity, Ipopt (its linear solves apart), our callbacks, and writing the result folder
/// (trajectory.csv and trajectory.json at 1 kHz and summary.json, no pictures). Problems: the
/// default five-link gait (configs/ocp/mu2004_walk.yaml, SSP 30 + DSP 6 Hermite-Simpson segments),
/// RABBIT after Kelly 2017 at 25 segments and the five-link cost-of-transport problem, each from
/// its polynomial guess, each with the config's linear solver (MUMPS) and with gaitopt's
/// (`ldl`, ocp/solve/kkt/). Every stage is the median of `repeats` runs in this process.
///
/// With `levers`, the same problems are solved under each solver setting of kLevers, the
/// settings interleaved run by run (so load from other jobs falls on all alike), and each
/// median is given as a ratio to the shipped setting's median of the same run.
/// With `--csv FILE`, the profile's medians are also written to FILE (results/solve_profile.csv,
/// which the README cites).
/// Usage: solve_profile [repeats] [levers | --csv FILE]
#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <functional>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <unistd.h>

#include <fmt/format.h>

#include "bench/mumps_calls.hpp"
#include "bench/ocp_bench_common.hpp"
#include "ocp/guess/initial_guess.hpp"
#include "ocp/solve/gait_solve.hpp"
#include "ocp/solve/solution_report.hpp"

namespace {

using namespace gaitopt;
using Clock = std::chrono::steady_clock;

struct Problem {
  std::string label;
  std::string file;           ///< under configs/ocp/
  int ssp_segments = 0;       ///< 0: the config's
  std::string linear_solver;  ///< "mumps" or "ldl"
};

/// Each problem with gaitopt's linear solver (ocp/solve/kkt/, the default) and with MUMPS on every
/// matrix; the first two rows are MUMPS's, on which the levers are measured.
const std::vector<Problem> kProblems = {
    {"five-link default (30+6), MUMPS", "mu2004_walk.yaml", 0, "mumps"},
    {"RABBIT Kelly 2017 (25), MUMPS", "rabbit_kelly2017.yaml", 25, "mumps"},
    {"five-link default (30+6), ldl", "mu2004_walk.yaml", 0, "ldl"},
    {"RABBIT Kelly 2017 (25), ldl", "rabbit_kelly2017.yaml", 25, "ldl"},
    {"five-link cost of transport (30+7), MUMPS", "mu2004_walk_cot.yaml", 0, "mumps"},
    {"five-link cost of transport (30+7), ldl", "mu2004_walk_cot.yaml", 0, "ldl"}};

/// A solver setting against the shipped one: a name and what it changes.
struct Lever {
  std::string name;
  std::function<void(ocp::SolverOptions&)> apply;
};

const std::vector<Lever> kLevers = {
    {"shipped", [](ocp::SolverOptions&) {}},
    {"mu_strategy monotone", [](ocp::SolverOptions& o) { o.mu_strategy = "monotone"; }},
    {"mu_strategy monotone, mu_init 1e-2",
     [](ocp::SolverOptions& o) {
       o.mu_strategy = "monotone";
       o.mu_init = 1e-2;
     }},
    {"mumps_pivot_order 7 (MUMPS chooses)", [](ocp::SolverOptions& o) { o.mumps_pivot_order = 7; }},
    {"mu_strategy adaptive", [](ocp::SolverOptions& o) { o.mu_strategy = "adaptive"; }},
    {"mumps_pivot_order 5 (METIS)", [](ocp::SolverOptions& o) { o.mumps_pivot_order = 5; }},
    {"nlp_scaling_method none", [](ocp::SolverOptions& o) { o.nlp_scaling_method = "none"; }},
    {"bound_push = bound_frac = 1e-4",
     [](ocp::SolverOptions& o) { o.bound_push = o.bound_frac = 1e-4; }},
    {"bound_mult_init_method constant",
     [](ocp::SolverOptions& o) { o.bound_mult_init_method = "constant"; }},
    {"tolerance 1e-6", [](ocp::SolverOptions& o) { o.tolerance = 1e-6; }},
    {"tolerance 1e-6, bound_mult_init_method constant",
     [](ocp::SolverOptions& o) {
       o.tolerance = 1e-6;
       o.bound_mult_init_method = "constant";
     }},
};
/// The levers are measured on the first two problems, with MUMPS (the cost-of-transport solve
/// is ten times longer and would dominate the run).
constexpr size_t kLeverProblems = 2;

/// One whole solve, stage by stage [s]; `cpu` is the process's CPU time of the whole solve,
/// steadier than wall time on a loaded machine.
struct Run {
  double cpu = 0, load = 0, guess = 0, build = 0, ipopt = 0, linear = 0, callbacks = 0,
         sparsity = 0;
  double write = 0, total = 0;
  bench::MumpsCalls mumps;  ///< inside Ipopt's linear solves
  int iterations = 0, factorizations = 0, kkt_dimension = 0, kkt_nonzeros = 0;
  double cost = 0;
  bool success = false;
};

double cpuSeconds() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

double since(Clock::time_point& t) {
  const auto now = Clock::now();
  const double s = std::chrono::duration<double>(now - t).count();
  t = now;
  return s;
}

Run solveOnce(const Problem& p, const Lever& lever, const std::string& out_dir) {
  Run r;
  const double cpu_start = cpuSeconds();
  auto t = Clock::now();
  const auto start = t;
  const std::string path = std::string(GAITOPT_SOURCE_DIR) + "/configs/ocp/" + p.file;
  ocp::OcpConfig config = ocp::loadOcpConfig(path);
  if (p.ssp_segments > 0) config.phases.front().segments = p.ssp_segments;
  config.solver.linear_solver = p.linear_solver;
  lever.apply(config.solver);
  const dynamics::Model model = ocp::problemModel(config);
  r.load = since(t);
  const gaits::Trajectory guess = ocp::polynomialGuess(model, config);
  r.guess = since(t);
  bench::resetMumpsCalls();
  const ocp::GaitSolution s = ocp::solveGait(model, config, guess);
  const double solve_gait = since(t);
  r.mumps = bench::mumpsCalls();
  std::filesystem::create_directories(out_dir);
  ocp::writeGaitResult({path, 1000, {}, {}}, model, config, s, nullptr, out_dir);
  r.write = since(t);
  r.total = std::chrono::duration<double>(t - start).count();
  r.cpu = cpuSeconds() - cpu_start;
  const ocp::SolveResult& res = s.result;
  r.sparsity = res.profile.sparsity_time_s;
  r.callbacks = res.callback_time_s;
  r.linear = res.profile.linear_solver_time_s;
  r.ipopt = res.wall_time_s - r.callbacks - r.sparsity;
  r.build = solve_gait - res.wall_time_s;  // the NLP and the mesh-error estimate
  r.iterations = res.iterations;
  r.factorizations = res.profile.factorizations;
  r.kkt_dimension = res.profile.kkt_dimension;
  r.kkt_nonzeros = res.profile.kkt_nonzeros;
  r.cost = res.cost;
  r.success = res.success;
  return r;
}

/// The median over the runs of `field`: a double member of Run, or a function of a run.
template <class Field>
double medianOf(const std::vector<Run>& runs, Field field) {
  std::vector<double> v;
  for (const Run& r : runs) v.push_back(std::invoke(field, r));
  return bench::median(v);
}

/// One problem's stage medians over its runs, and its last run for the counts (the same in
/// every run).
struct Medians {
  const Run* last = nullptr;
  double cpu = 0, total = 0, load = 0, guess = 0, build = 0, sparsity = 0, ipopt = 0, linear = 0,
         callbacks = 0, write = 0;
  double analysis = 0, factorization = 0, solve = 0;  ///< MUMPS's phases

  /// Setup and output, everything of a solve but Ipopt and our callbacks.
  double setup() const { return load + guess + build + sparsity + write; }
  double mumps() const { return analysis + factorization + solve; }
};

/// A run's time in one MUMPS phase, for medianOf.
auto secondsIn(bench::MumpsPhase bench::MumpsCalls::*phase) {
  return [phase](const Run& r) { return (r.mumps.*phase).seconds; };
}

Medians mediansOf(const std::vector<Run>& rs) {
  using C = bench::MumpsCalls;
  return {&rs.back(),
          medianOf(rs, &Run::cpu),
          medianOf(rs, &Run::total),
          medianOf(rs, &Run::load),
          medianOf(rs, &Run::guess),
          medianOf(rs, &Run::build),
          medianOf(rs, &Run::sparsity),
          medianOf(rs, &Run::ipopt),
          medianOf(rs, &Run::linear),
          medianOf(rs, &Run::callbacks),
          medianOf(rs, &Run::write),
          medianOf(rs, secondsIn(&C::analysis)),
          medianOf(rs, secondsIn(&C::factorization)),
          medianOf(rs, secondsIn(&C::solve))};
}

void printProfile(const std::vector<Medians>& problems) {
  fmt::print(
      "| problem | iterations | factorizations | KKT dim | KKT nnz | cost J | total CPU s | total "
      "s | "
      "load s | "
      "guess s | build s | sparsity s | Ipopt s | (linear solves s) | callbacks s | write s | "
      "setup share |\n"
      "|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  for (size_t i = 0; i < kProblems.size(); ++i) {
    const Medians& m = problems[i];
    const Run& last = *m.last;
    fmt::print(
        "| {} | {} | {} | {} | {} | {:.6g} | {:.4f} | {:.4f} | {:.4f} | {:.4f} | {:.4f} | {:.4f} "
        "| {:.4f} | {:.4f} | {:.4f} | {:.4f} | {:.0f} % |\n",
        kProblems[i].label, last.iterations, last.factorizations, last.kkt_dimension,
        last.kkt_nonzeros, last.cost, m.cpu, m.total, m.load, m.guess, m.build, m.sparsity, m.ipopt,
        m.linear, m.callbacks, m.write, 100 * m.setup() / m.total);
  }
}

/// MUMPS's part of each solve: its analysis, factorizations and back-solves (the linear solves
/// column of the profile holds them and Ipopt's own work around them).
void printMumps(const std::vector<Medians>& problems) {
  fmt::print(
      "\n| problem | analyses | analysis s | factorizations | s each | back-solves | s each | "
      "MUMPS "
      "s | of the whole solve |\n|---|---:|---:|---:|---:|---:|---:|---:|---:|\n");
  for (size_t i = 0; i < kProblems.size(); ++i) {
    const Medians& m = problems[i];
    const bench::MumpsCalls& last = m.last->mumps;
    if (last.factorization.calls == 0) continue;  // solved without MUMPS
    fmt::print("| {} | {} | {:.4f} | {} | {:.4f} | {} | {:.4f} | {:.4f} | {:.0f} % |\n",
               kProblems[i].label, last.analysis.calls, m.analysis, last.factorization.calls,
               m.factorization / last.factorization.calls, last.solve.calls,
               m.solve / last.solve.calls, m.mumps(), 100 * m.mumps() / m.total);
  }
}

/// "N CPUs, model name" from /proc/cpuinfo, for the machine a profile was measured on.
std::string machine() {
  std::ifstream in("/proc/cpuinfo");
  std::string model = "unknown CPU";
  for (std::string line; std::getline(in, line);)
    if (line.rfind("model name", 0) == 0) {
      model = line.substr(line.find(':') + 2);
      break;
    }
  return fmt::format("{} CPUs, {}", std::thread::hardware_concurrency(), model);
}

/// The profile's medians as CSV, one row per problem, for the README (scripts/docs.py).
void writeProfileCsv(const std::vector<Medians>& problems, const std::string& path) {
  std::ofstream out(path);
  out << "problem,machine,iterations,factorizations,kkt_dim,kkt_nnz,cost,total_cpu_s,total_s,"
         "setup_s,setup_share,ipopt_s,linear_solves_s,callbacks_s,write_s,mumps_analysis_s,"
         "mumps_factorizations,"
         "mumps_factorization_s,mumps_back_solves,mumps_back_solve_s,mumps_s\n";
  const std::string where = machine();
  for (size_t i = 0; i < kProblems.size(); ++i) {
    const Medians& m = problems[i];
    const Run& last = *m.last;
    out << fmt::format(
        "\"{}\",\"{}\",{},{},{},{},{:.9g},{:.4f},{:.4f},{:.4f},{:.3f},{:.4f},{:.4f},{:.4f},{:.4f},{"
        ":."
        "4f},"
        "{},{:.4f},{},{:.4f},{:.4f}\n",
        kProblems[i].label, where, last.iterations, last.factorizations, last.kkt_dimension,
        last.kkt_nonzeros, last.cost, m.cpu, m.total, m.setup(), m.setup() / m.total, m.ipopt,
        m.linear, m.callbacks, m.write, m.analysis, last.mumps.factorization.calls, m.factorization,
        last.mumps.solve.calls, m.solve, m.mumps());
  }
  if (!out) throw std::runtime_error("cannot write " + path);
}

void printLevers(const std::vector<std::vector<std::vector<Run>>>& runs) {
  fmt::print(
      "| problem | setting | converged | iterations | factorizations | cost J | total CPU s | "
      "total s | CPU / shipped | wall / shipped |\n"
      "|---|---|---|---:|---:|---:|---:|---:|---:|---:|\n");
  for (size_t i = 0; i < kLeverProblems; ++i) {
    const double cpu = medianOf(runs[i][0], &Run::cpu), wall = medianOf(runs[i][0], &Run::total);
    for (size_t l = 0; l < kLevers.size(); ++l) {
      const auto& rs = runs[i][l];
      const bool all = std::all_of(rs.begin(), rs.end(), [](const Run& r) { return r.success; });
      fmt::print("| {} | {} | {} | {} | {} | {:.7g} | {:.4f} | {:.4f} | {:.2f} | {:.2f} |\n",
                 kProblems[i].label, kLevers[l].name, all ? "yes" : "no", rs.back().iterations,
                 rs.back().factorizations, rs.back().cost, medianOf(rs, &Run::cpu),
                 medianOf(rs, &Run::total), medianOf(rs, &Run::cpu) / cpu,
                 medianOf(rs, &Run::total) / wall);
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  const int repeats = argc > 1 ? std::max(1, std::atoi(argv[1])) : 7;
  const bool levers = argc > 2 && std::string(argv[2]) == "levers";
  const std::string csv = argc > 3 && std::string(argv[2]) == "--csv" ? argv[3] : "";
  if (argc > 2 && !levers && csv.empty()) {
    fmt::print(stderr, "usage: solve_profile [repeats] [levers | --csv FILE]\n");
    return 2;
  }
  const size_t settings = levers ? kLevers.size() : 1;
  const std::string out =
      (std::filesystem::temp_directory_path() / fmt::format("solve_profile.{}", ::getpid()))
          .string();
  // runs[problem][setting][repeat], the settings interleaved within each repeat
  std::vector<std::vector<std::vector<Run>>> runs(kProblems.size(),
                                                  std::vector<std::vector<Run>>(settings));
  const size_t problems = levers ? kLeverProblems : kProblems.size();
  for (int k = 0; k < repeats; ++k)
    for (size_t i = 0; i < problems; ++i)
      for (size_t l = 0; l < settings; ++l)
        runs[i][l].push_back(solveOnce(kProblems[i], kLevers[l], out));
  std::filesystem::remove_all(out);
  fmt::print("Medians of {} runs per row in one process; times are wall clock.\n\n", repeats);
  if (!levers) {
    std::vector<Medians> shipped;
    for (const auto& r : runs) shipped.push_back(mediansOf(r[0]));
    printProfile(shipped);
    printMumps(shipped);
    if (!csv.empty()) writeProfileCsv(shipped, csv);
  } else {
    printLevers(runs);
  }
  return 0;
}
