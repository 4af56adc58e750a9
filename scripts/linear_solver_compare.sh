#!/usr/bin/env bash
# Every shipped OCP config (configs/ocp/*.yaml) solved with MUMPS and with gaitopt's KKT solver
# (solver.linear_solver: ldl, ocp/solve/kkt/): status, iterations, cost and wall time of each, as a
# markdown table with how many of the KKT solver's factorizations needed its pivoting
# factorization and how many went to MUMPS (summary.json's kkt) and, with CSV, a file
# (results/linear_solver_compare.csv). Each solver's copy of
# the configs is made by scripts/solver_configs.sh in a temporary folder.
# Usage: scripts/linear_solver_compare.sh BUILD_DIR [CSV]   (about 1 minute)
set -euo pipefail

if [[ $# -lt 1 || $# -gt 2 ]]; then
  echo "usage: $0 BUILD_DIR [CSV]" >&2
  exit 2
fi
gaitopt="$1/apps/gaitopt"
csv_out="${2:-}"
[[ -x "$gaitopt" ]] || { echo "error: $gaitopt not built" >&2; exit 1; }
root="$(cd "$(dirname "$0")/.." && pwd)"
work="$(mktemp -d "${TMPDIR:-/tmp}/linear_solver_compare.XXXXXX")"
trap 'rm -rf "$work"' EXIT
for solver in mumps ldl; do "$root/scripts/solver_configs.sh" "$work/$solver" "$solver"; done

rows="$work/rows.csv"
echo "config,linear_solver,status,iterations,cost,wall_s,factorizations,mumps_fallbacks,inertia_corrections,pivoting_factorizations" >"$rows"
for config in "$root"/configs/ocp/*.yaml; do
  name="$(basename "$config" .yaml)"
  for solver in mumps ldl; do
    "$root/scripts/solve_row.sh" "$gaitopt" "$work/$solver/ocp/$name.yaml" \
      "$work/out_${solver}_$name" "$name" "$solver" >>"$rows"
  done
done

/usr/bin/python3 - "$rows" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
print("| config | MUMPS: status, iterations, cost, solve s | ldl: status, iterations, cost, solve s | same optimum | ldl's factorizations with pivoting | made by MUMPS |")
print("|---|---|---|---|---|---|")
for m, l in zip(rows[0::2], rows[1::2]):
    cm, cl = float(m["cost"]), float(l["cost"])
    same = "yes" if m["status"] == l["status"] == "Solve_Succeeded" and abs(cm - cl) <= 1e-6 * max(abs(cm), 1e-12) else "no"
    cell = lambda r: f"{r['status']}, {r['iterations']}, {float(r['cost']):.7g}, {float(r['wall_s']):.3f}"
    pivoting = f"{l['pivoting_factorizations']} of {l['factorizations']}"
    share = f"{l['mumps_fallbacks']} of {l['factorizations']}"
    print(f"| {m['config']} | {cell(m)} | {cell(l)} | {same} | {pivoting} | {share} |")
PY
if [[ -n "$csv_out" ]]; then cp "$rows" "$csv_out"; fi
