#!/usr/bin/env bash
# Points per second of `gaitopt library` on this machine: the 9-point library of
# configs/library/throughput.yaml solved from scratch with 1 worker process, with 2, and as 2
# MPI ranks of 1 worker each (mpirun --oversubscribe -np 2), all with the default linear solver
# (gaitopt's, ocp/solve/kkt/), and with 1 and 2 worker processes under MUMPS on every matrix (the same
# library whose OCP config says linear_solver: mumps, copied to a temporary folder), REPEATS
# times each, interleaved so that load from other jobs falls on every mode alike. Prints a
# markdown table of medians and the ratio to the 1-worker median, and how many points the
# default solves to MUMPS's optimum; with CSV, also writes the medians there (the README cites
# results/library_throughput.csv).
# Usage: scripts/library_throughput.sh BUILD_DIR [REPEATS [CSV]]   (default 3 repeats)
set -euo pipefail

if [[ $# -lt 1 || $# -gt 3 ]]; then
  echo "usage: $0 BUILD_DIR [REPEATS [CSV]]" >&2
  exit 2
fi
gaitopt="$1/apps/gaitopt"
repeats="${2:-3}"
csv_out="${3:-}"
[[ -x "$gaitopt" ]] || { echo "error: $gaitopt not built" >&2; exit 1; }
root="$(cd "$(dirname "$0")/.." && pwd)"
config="$root/configs/library/throughput.yaml"
work="$(mktemp -d "${TMPDIR:-/tmp}/library_throughput.XXXXXX")"
trap 'rm -rf "$work"' EXIT
mumps="$work/configs"  # configs/ whose OCP configs select linear_solver: mumps
"$root/scripts/solver_configs.sh" "$mumps" mumps
# OpenMPI refuses root unless told; CI runs as root.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

run() {  # run MODE REPEAT: one library from scratch, its points/s appended to MODE.txt
  local mode="$1" out="$work/$1-$2"
  case "$mode" in
    1-process) "$gaitopt" library --config "$config" --out "$out" --jobs 1 --quiet >/dev/null ;;
    2-processes) "$gaitopt" library --config "$config" --out "$out" --jobs 2 --quiet >/dev/null ;;
    2-mpi-ranks) mpirun --oversubscribe -np 2 "$gaitopt" library --config "$config" \
                   --out "$out" --quiet >/dev/null ;;
    1-process-mumps) "$gaitopt" library --config "$mumps/library/throughput.yaml" --out "$out" \
                       --jobs 1 --quiet >/dev/null ;;
    2-processes-mumps) "$gaitopt" library --config "$mumps/library/throughput.yaml" \
                         --out "$out" --jobs 2 --quiet >/dev/null ;;
  esac
  /usr/bin/python3 -c "import json,sys; d=json.load(open(sys.argv[1]))
print(d['last_run']['points_per_second'], d['points_solved'], d['last_run']['wall_time_s'])" \
    "$out/index.json" >>"$work/$mode.txt"
}

modes=(1-process 2-processes)
command -v mpirun >/dev/null && modes+=(2-mpi-ranks)
modes+=(1-process-mumps 2-processes-mumps)
for r in $(seq "$repeats"); do
  for m in "${modes[@]}"; do
    echo "library_throughput: $m, run $r of $repeats" >&2
    run "$m" "$r"
  done
done

cpu="$(sed -n 's/^model name[[:space:]]*:[[:space:]]*//p' /proc/cpuinfo | head -n 1)"
echo "Machine: $(nproc) CPUs, ${cpu:-unknown CPU}; date: $(date -u '+%Y-%m-%d %H:%M:%S UTC')"
echo "Library: configs/library/throughput.yaml (9 points), medians of $repeats runs"
echo
/usr/bin/python3 - "$work" "$csv_out" "${modes[@]}" <<'PY'
import csv, statistics, sys
work, csv_out, modes = sys.argv[1], sys.argv[2], sys.argv[3:]
rows = {}
for m in modes:
    runs = [tuple(map(float, line.split())) for line in open(f"{work}/{m}.txt")]
    rows[m] = (statistics.median(r[0] for r in runs), statistics.median(r[2] for r in runs),
               min(int(r[1]) for r in runs))
base = rows["1-process"][0]
print("| mode | points/s (median) | wall time s (median) | points solved (min) | ratio to 1 process |")
print("|---|---:|---:|---:|---:|")
for m in modes:
    pps, wall, solved = rows[m]
    print(f"| {m} | {pps:.3f} | {wall:.1f} | {solved}/9 | {pps / base:.2f} |")
if csv_out:
    with open(csv_out, "w", newline="") as f:
        out = csv.writer(f)
        out.writerow(["mode", "points_per_second", "wall_time_s", "points_solved", "ratio"])
        for m in modes:
            pps, wall, solved = rows[m]
            out.writerow([m, f"{pps:.3f}", f"{wall:.2f}", solved, f"{pps / base:.2f}"])
PY
# The default is worth its speed only if it solves the same library: compare each point's
# iterations and cost between the first 1-process-mumps run and the first 1-process run.
/usr/bin/python3 - "$work/1-process-mumps-1/index.csv" "$work/1-process-1/index.csv" <<'PY'
import csv, sys
mumps, ldl = ({r["point"]: r for r in csv.DictReader(open(p))} for p in sys.argv[1:])
same = sum(1 for p, r in mumps.items() if p in ldl and r["iterations"] == ldl[p]["iterations"]
           and abs(float(r["cost"]) - float(ldl[p]["cost"])) <= 1e-9 * abs(float(r["cost"])))
print(f"\nWith ldl, {same} of {len(mumps)} points take MUMPS's iterations to its cost (within 1e-9).")
PY
