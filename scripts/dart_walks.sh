#!/usr/bin/env bash
# The five-link optima walked in the DART physics engine (configs/grounds/dart.yaml, a build with
# -DGAITOPT_DART=ON): the torque-squared optimum (configs/ocp/mu2004_walk.yaml, lands at rest),
# the strike optimum (mu2004_walk_strike.yaml) and the gait designed to be walked
# (mu2004_walk_robust.yaml), 20 steps each under computed torque and Mu's sliding mode, on plants
# with masses and inertias 0.9, 1.0 and 1.1 times the model's (--mass-error), with the strict CoP
# rule of the other closed-loop results (--cop-limit fail). Writes OUT/dart_walks.csv and
# OUT/dart_walks.md; "of 10" is the first ten steps of the same walk.
# Usage: scripts/dart_walks.sh BUILD_DIR OUT_DIR   (from the repository root)
set -euo pipefail
build=${1:?usage: $0 BUILD_DIR OUT_DIR}
out=${2:?usage: $0 BUILD_DIR OUT_DIR}
bin="$build/apps/gaitopt"
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p "$out"
gaits=(mu2004_walk mu2004_walk_strike mu2004_walk_robust)
for gait in "${gaits[@]}"; do
  "$bin" optimize --config "configs/ocp/$gait.yaml" --out "$work/ref_$gait" --no-plots \
    --quiet >/dev/null
done
echo "gait,controller,plant_mass,steps,max_tracking_error_rad,max_slip_m,failure" \
  >"$out/dart_walks.csv"
for gait in "${gaits[@]}"; do
  for controller in computed_torque mu_sliding_mode; do
    for mass in -0.1 0 0.1; do
      "$bin" simulate --reference "$work/ref_$gait" --ground dart --controller "$controller" \
        --mass-error="$mass" --cop-limit fail --steps 20 --out "$work/walk" --no-plots \
        --no-poincare --quiet >/dev/null
      /usr/bin/python3 scripts/walk_row.py "$work/walk/summary.json" "$gait" "$controller" \
        "$(awk "BEGIN { printf \"%.1f\", 1 + $mass }")" >>"$out/dart_walks.csv"
    done
  done
done
/usr/bin/python3 - "$out/dart_walks.csv" >"$out/dart_walks.md" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
masses = list(dict.fromkeys(r["plant_mass"] for r in rows))
print("| gait | controller | " + " | ".join(f"plant mass x{m}" for m in masses) + " |")
print("|---|---|" + "---|" * len(masses))
key = lambda r: (r["gait"], r["controller"])
for k in dict.fromkeys(key(r) for r in rows):
    cells = []
    for r in (r for r in rows if key(r) == k):
        n = int(r["steps"])
        step, _, rest = r["failure"].partition(": ")
        why = "" if n == 20 else f" ({step}: {rest.split(':')[0]})"
        cells.append(f"{min(n, 10)} of 10, {n} of 20{why}")
    print(f"| `{k[0]}` | {k[1]} | " + " | ".join(cells) + " |")
PY
cat "$out/dart_walks.md"
