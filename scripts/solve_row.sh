#!/usr/bin/env bash
# One `gaitopt optimize` of CONFIG, written to OUT (OUT.failed if it fails), as a CSV row:
# the LABELs, then the solve's status, iterations, cost and wall time (summary.json's
# wall_time_s, the solve without writing the folder), then its KKT factorizations, how many of
# them MUMPS made for gaitopt's KKT solver, Ipopt's inertia corrections, and how many of them
# gaitopt's pivoting factorization made (summary.json's kkt). The row for the solver comparisons:
# scripts/linear_solver_compare.sh, scripts/solver_robustness.sh.
# Usage: scripts/solve_row.sh GAITOPT CONFIG OUT [LABEL ...]
set -euo pipefail

if [[ $# -lt 3 ]]; then
  echo "usage: $0 GAITOPT CONFIG OUT [LABEL ...]" >&2
  exit 2
fi
gaitopt="$1"
config="$2"
out="$3"
shift 3
rm -rf "$out" "$out.failed"
"$gaitopt" optimize --config "$config" --out "$out" --no-plots --quiet >/dev/null 2>&1 || true
[[ -d "$out" ]] || out="$out.failed"
/usr/bin/python3 - "$out/summary.json" "$@" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
labels = "".join(f"{label}," for label in sys.argv[2:])
k = s["kkt"]
print(f"{labels}{s['status']},{s['iterations']},{s['cost']!r},{s['wall_time_s']:.4f},"
      f"{k['factorizations']},{k['mumps_fallbacks']},{k['inertia_corrections']},"
      f"{k['pivoting_factorizations']}")
PY
