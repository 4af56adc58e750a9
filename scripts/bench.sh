#!/usr/bin/env bash
# Runs the dynamics micro-benchmarks and prints a markdown table of per-benchmark median and
# minimum time over 15 repetitions, with the ratio of each median to BM_MassMatrix's; then
# the OCP solve-time table (bench/ocp_bench.cpp), the default's whole solves paired against
# its double support in theta (scripts/paired_times.py), the solve-time profile (where a
# whole solve's time goes, and the solver settings measured against the shipped ones,
# bench/solve_profile.cpp), every shipped config with MUMPS and with gaitopt's KKT solver
# (configs/studies/linear_solver_compare.yaml) and how often each converges on the five-link
# configs at five meshes (configs/studies/solver_robustness.yaml), how often every shipped problem converges over
# meshes and starts (bench/convergence_bench.cpp), the ensemble's solve time with 1, 3 and 5
# models (bench/ensemble_bench.cpp), the double support in theta
# against reduced coordinates (bench/dsp_coordinates.cpp), the chapter-5 impact figures against
# the link inertias (bench/impact_sensitivity.cpp), the passive walker's bifurcation
# diagram (bench/passive_bifurcation.cpp, plots/passive_bifurcation_chart.py), then the
# speed-against-accuracy table and chart
# of the ground models (bench/ground_bench.cpp, plots/ground_chart.py).
# Usage: scripts/bench.sh BUILD_DIR   (BUILD_DIR configured with GAITOPT_BUILD_BENCH=ON, built)
set -euo pipefail

if [[ $# -ne 1 ]]; then
  echo "usage: $0 BUILD_DIR" >&2
  exit 2
fi
bin="$1/bench/dynamics_bench"
if [[ ! -x "$bin" ]]; then
  echo "error: benchmark binary not found or not executable: $bin" >&2
  echo "       build it first: cmake -S . -B $1 -G Ninja && cmake --build $1 -j2" >&2
  exit 1
fi

json="$(mktemp "${TMPDIR:-/tmp}/dynamics_bench.XXXXXX.json")"
trap 'rm -f "$json"' EXIT

# Every repetition is reported (no aggregates_only) so the minimum can be computed below.
"$bin" --benchmark_repetitions=15 --benchmark_min_time=0.05 --benchmark_format=json >"$json"

cpu="$(sed -n 's/^model name[[:space:]]*:[[:space:]]*//p' /proc/cpuinfo | head -n 1)"
echo "Machine: $(nproc) CPUs, ${cpu:-unknown CPU}; date: $(date -u '+%Y-%m-%d %H:%M:%S UTC')"
echo

/usr/bin/python3 - "$json" <<'PY'
import json
import statistics
import sys

with open(sys.argv[1]) as f:
    data = json.load(f)

scale = {"ns": 1.0, "us": 1e3, "ms": 1e6, "s": 1e9}
times = {}  # benchmark name -> per-repetition real time [ns], in the binary's order
for b in data["benchmarks"]:
    if b.get("run_type") != "iteration":
        continue  # aggregates (mean, median, stddev, cv), should any be present
    if "error_occurred" in b and b["error_occurred"]:
        sys.exit(f"error: {b['run_name']}: {b.get('error_message', 'benchmark failed')}")
    times.setdefault(b["run_name"], []).append(b["real_time"] * scale[b["time_unit"]])

if "BM_MassMatrix" not in times:
    sys.exit("error: BM_MassMatrix missing from the benchmark output")
ref = statistics.median(times["BM_MassMatrix"])
print("| benchmark | median ns | min ns | ratio to BM_MassMatrix median |")
print("|---|---:|---:|---:|")
for name, t in times.items():
    med = statistics.median(t)
    print(f"| {name} | {med:.1f} | {min(t):.1f} | {med / ref:.2f} |")
reps = {len(t) for t in times.values()}
print(f"\nRepetitions per benchmark: {', '.join(str(r) for r in sorted(reps))}; real time.")
PY

echo
ocp="$1/bench/ocp_bench"
[[ -x "$ocp" ]] || { echo "error: $ocp not built" >&2; exit 1; }
"$ocp" 5

echo
gaitopt="$1/apps/gaitopt"
[[ -x "$gaitopt" ]] || { echo "error: $gaitopt not built" >&2; exit 1; }
default_case="$gaitopt:configs/ocp/mu2004_walk.yaml"
echo "The five-link default against its double support in theta as shipped until 2026-11-29 (six"
echo "equal segments) and without Ipopt's own refinement step, whole processes run in turn:"
/usr/bin/python3 scripts/paired_times.py --runs 15 --out "$1/paired_times.md" \
  "theta=$default_case:constraints.dsp_reduced_coordinates=false:phases[1].first_segment=0.16666666666666667" \
  "default=$default_case" "no_ipopt_refinement=$default_case:solver.min_refinement_steps=0"
echo "(also in $1/paired_times.{md,csv}; results/paired_times.{md,csv} are copies)"

echo
profile="$1/bench/solve_profile"
[[ -x "$profile" ]] || { echo "error: $profile not built" >&2; exit 1; }
echo "Load average before the solve profile: $(cut -d' ' -f1-3 /proc/loadavg)"
"$profile" 5 --csv "$1/solve_profile.csv"
echo "(medians also in $1/solve_profile.csv; results/solve_profile.csv, cited by the README, is a copy)"
echo
"$profile" 5 levers

echo
# study BUILD NAME TABLE: a fresh run of the study configs/studies/NAME.yaml into BUILD/NAME/,
# then its TABLE.
study() {
  rm -rf "${1:?}/$2"
  "$1/apps/gaitopt" study --config "configs/studies/$2.yaml" --out "$1/$2" --quiet
  cat "$1/$2/$3"
}
echo "Every shipped config with MUMPS and with gaitopt's KKT solver (linear_solver: ldl):"
study "$1" linear_solver_compare solves.md
echo "(also in $1/linear_solver_compare/; results/linear_solver_compare/ holds its tables)"
echo
echo "How often each solver converges on the five-link configs at five meshes:"
study "$1" solver_robustness by_axis.md
echo "(also in $1/solver_robustness/; results/solver_robustness/ holds its tables)"
echo
echo "How often every shipped problem converges over five meshes and two starts, and where to:"
conv="$1/bench/convergence_bench"
[[ -x "$conv" ]] || { echo "error: $conv not built" >&2; exit 1; }
"$conv" "$1/convergence.csv" 2>/dev/null | tee "$1/convergence.md"
echo "(also in $1/convergence.{csv,md}; results/convergence.{csv,md} are copies)"

echo
ensemble="$1/bench/ensemble_bench"
[[ -x "$ensemble" ]] || { echo "error: $ensemble not built" >&2; exit 1; }
"$ensemble" 3 | tee "$1/ensemble_bench.md"
echo "(also in $1/ensemble_bench.md; results/ensemble_bench.md is a copy)"

echo
dsp="$1/bench/dsp_coordinates"
[[ -x "$dsp" ]] || { echo "error: $dsp not built" >&2; exit 1; }
"$dsp" 3

# study_into BUILD NAME TABLE: runs BUILD/bench/NAME into BUILD/NAME/ and prints its TABLE.
study_into() {
  local bin="$1/bench/$2"
  [[ -x "$bin" ]] || { echo "error: $bin not built" >&2; exit 1; }
  mkdir -p "$1/$2"
  "$bin" "$1/$2"
  cat "$1/$2/$3"
}

echo
study_into "$1" impact_sensitivity sensitivity.md
echo "(also in $1/impact_sensitivity/; results/impact_sensitivity/ is a copy)"

echo
study_into "$1" passive_bifurcation bifurcation.md
/usr/bin/python3 plots/passive_bifurcation_chart.py "$1/passive_bifurcation"
echo "(also in $1/passive_bifurcation/; results/passive_bifurcation/ is a copy)"

echo
ground="$1/bench/ground_bench"
[[ -x "$ground" ]] || { echo "error: $ground not built" >&2; exit 1; }
csv="$(mktemp -d "${TMPDIR:-/tmp}/ground_bench.XXXXXX")/ground_bench.csv"
"$ground" 3 >"$csv"
/usr/bin/python3 plots/ground_chart.py "$csv"
