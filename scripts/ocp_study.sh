#!/usr/bin/env bash
# The collocation study (bench/ocp_study.cpp): speed against accuracy of the OCP by
# scheme and mesh, by derivative mode, and by initial guess, on RABBIT (Kelly 2017) and the
# five-link default problem; then the charts and markdown tables
# (plots/ocp_study_charts.py). Writes OUT_DIR/{collocation,derivatives,guesses}.{csv,md}
# and the PNGs. About 5 minutes on a 2-core machine (307 s measured; most of it the five-link
# limited-memory solves that run to the iteration limit and the five-link perturbed guesses),
# so scripts/bench.sh does not run it: run it on its own.
# Usage: scripts/ocp_study.sh BUILD_DIR OUT_DIR [REPEATS] [SEEDS]
#   BUILD_DIR built with the ocp_study target; REPEATS solves per timing (default 3), SEEDS
#   perturbed guesses per noise level (default 10).
set -euo pipefail

if [[ $# -lt 2 || $# -gt 4 ]]; then
  echo "usage: $0 BUILD_DIR OUT_DIR [REPEATS] [SEEDS]" >&2
  exit 2
fi
bin="$1/bench/ocp_study"
out="$2"
repeats="${3:-3}"
seeds="${4:-10}"
if [[ ! -x "$bin" ]]; then
  echo "error: study binary not found or not executable: $bin" >&2
  echo "       build it first: cmake --build $1 -j2 --target ocp_study" >&2
  exit 1
fi
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
mkdir -p "$out"

cpu="$(sed -n 's/^model name[[:space:]]*:[[:space:]]*//p' /proc/cpuinfo | head -n 1)"
echo "Machine: $(nproc) CPUs, ${cpu:-unknown CPU}; date: $(date -u '+%Y-%m-%d %H:%M:%S UTC')"
start=$SECONDS
# Each CSV is written under a temporary name and renamed when complete, so an interrupted run
# never leaves a truncated CSV for the charts.
for study in collocation derivatives guesses; do
  "$bin" "$study" --repeats "$repeats" --seeds "$seeds" >"$out/$study.csv.tmp"
  mv "$out/$study.csv.tmp" "$out/$study.csv"
done
/usr/bin/python3 "$root/plots/ocp_study_charts.py" "$out"
echo "ocp_study.sh: $((SECONDS - start)) s"
