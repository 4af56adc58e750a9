#!/usr/bin/env bash
# How often each linear solver's Ipopt path converges on the path-sensitive five-link problems,
# and to which optimum: every five-link OCP config (configs/ocp/mu2004_walk*.yaml) at five SSP
# meshes (24 to 36 segments), solved with MUMPS under gaitopt's order (AMD, mumps_pivot_order 0),
# MUMPS under its own automatic order (mumps_pivot_order 7, Ipopt's default) and gaitopt's KKT
# solver (ldl). One config at one mesh is one draw of rounding: the three differ only in the
# rounding of their linear solves, so a config one solver converges on and another not is
# path sensitivity, and the success rate over the draws is what compares them. Prints a markdown
# table and, with CSV, writes the rows (results/solver_robustness.csv).
# Usage: scripts/solver_robustness.sh BUILD_DIR [CSV]   (about 5 minutes)
set -euo pipefail

if [[ $# -lt 1 || $# -gt 2 ]]; then
  echo "usage: $0 BUILD_DIR [CSV]" >&2
  exit 2
fi
gaitopt="$1/apps/gaitopt"
csv_out="${2:-}"
[[ -x "$gaitopt" ]] || { echo "error: $gaitopt not built" >&2; exit 1; }
root="$(cd "$(dirname "$0")/.." && pwd)"
work="$(mktemp -d "${TMPDIR:-/tmp}/solver_robustness.XXXXXX")"
trap 'rm -rf "$work"' EXIT
solvers=(mumps mumps-auto ldl)
for solver in "${solvers[@]}"; do
  "$root/scripts/solver_configs.sh" "$work/$solver" "${solver%-auto}"
done
# MUMPS's automatic order: the solver line gains mumps_pivot_order 7.
sed -i 's/^  linear_solver: mumps$/  linear_solver: mumps\n  mumps_pivot_order: 7/' \
  "$work"/mumps-auto/ocp/*.yaml

rows="$work/rows.csv"
echo "config,ssp_segments,solver,status,iterations,cost,wall_s,factorizations,mumps_fallbacks,inertia_corrections,pivoting_factorizations" >"$rows"
for config in "$root"/configs/ocp/mu2004_walk*.yaml; do
  name="$(basename "$config" .yaml)"
  grep -q '{name: SSP, .*segments: 30}' "$config" || { echo "error: $name: no 30-segment SSP" >&2; exit 1; }
  for segments in 24 27 30 33 36; do
    for solver in "${solvers[@]}"; do
      variant="$work/$solver/ocp/${name}_$segments.yaml"
      sed "s/\({name: SSP, .*segments: \)30}/\1$segments}/" "$work/$solver/ocp/$name.yaml" >"$variant"
      "$root/scripts/solve_row.sh" "$gaitopt" "$variant" "$work/out" "$name" "$segments" \
        "$solver" >>"$rows"
      echo "  $name, $segments segments, $solver: $(tail -n 1 "$rows" | cut -d, -f4-6)" >&2
    done
  done
done

/usr/bin/python3 - "$rows" "${solvers[@]}" <<'PY'
import csv, statistics, sys
rows = list(csv.DictReader(open(sys.argv[1])))
solvers = sys.argv[2:]
ok = lambda r: r["status"] == "Solve_Succeeded"
def best(key):  # the least cost any solver converged to on this draw
    costs = [float(r["cost"]) for r in rows if (r["config"], r["ssp_segments"]) == key and ok(r)]
    return min(costs) if costs else None
print("| solver | converged | to the best optimum found | median iterations | median solve s |")
print("|---|---:|---:|---:|---:|")
for s in solvers:
    mine = [r for r in rows if r["solver"] == s]
    conv = [r for r in mine if ok(r)]
    at_best = [r for r in conv
               if float(r["cost"]) <= best((r["config"], r["ssp_segments"])) * (1 + 1e-6) + 1e-12]
    print(f"| {s} | {len(conv)} of {len(mine)} | {len(at_best)} | "
          f"{statistics.median(int(r['iterations']) for r in mine):.0f} | "
          f"{statistics.median(float(r['wall_s']) for r in mine):.3f} |")
PY
if [[ -n "$csv_out" ]]; then cp "$rows" "$csv_out"; fi
