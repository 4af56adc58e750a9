#!/usr/bin/env bash
# Mu (2004) sec. 4.3's uncertainty cases in closed loop: the polynomial gait, the torque-squared
# optimal five-link gait and the two designed to be walked (mu2004_walk_robust, the ensemble
# mu2004_walk_ensemble), walked 20 steps on rigid ground by computed torque, the boundary-layer
# law (sliding_mode) and Mu's integral sliding mode (mu_sliding_mode), with the controller's
# model off by case 1 (exact), 2 (+40 % m, I; +10 % l, d) or 3 (+100 %, +40 %); on the shipped
# robot (5 cm heel: the stance ankle saturates where the CoP reaches the heel or the toe) and on
# the same robot with a 0.30 m heel (Mu's assumption: the ankle carries what the gait asks).
# Writes OUT/mu_cases.csv and OUT/mu_cases.md.
# Usage: scripts/mu_cases.sh BUILD_DIR OUT_DIR   (from the repository root)
set -euo pipefail
# shellcheck source=scripts/study_setup.sh
source "$(dirname "$0")/study_setup.sh" "$@"  # build, out, bin, work
"$bin" poly --robot configs/robots/mu2004_five_link.yaml --gait configs/gaits/mu2004.yaml \
  --out "$work/poly" --no-plots >/dev/null
"$bin" optimize --config configs/ocp/mu2004_walk.yaml --out "$work/opt" --no-plots --quiet >/dev/null
"$bin" optimize --config configs/ocp/mu2004_walk_robust.yaml --out "$work/opt_robust" --no-plots \
  --quiet >/dev/null
"$bin" optimize --config configs/ocp/mu2004_walk_ensemble.yaml --out "$work/opt_ensemble" \
  --no-plots --quiet >/dev/null
declare -A robots=([shipped]=configs/robots/mu2004_five_link.yaml
  [long_heel]=tests/apps/mu2004_five_link_long_heel.yaml)
echo "gait,robot,controller,case,steps,max_tracking_error_rad,max_slip_m,failure" >"$out/mu_cases.csv"
for gait in poly opt opt_robust opt_ensemble; do
  for robot in shipped long_heel; do
    for controller in computed_torque sliding_mode mu_sliding_mode; do
      for c in 1 2 3; do
        "$bin" simulate --reference "$work/$gait" --robot "${robots[$robot]}" \
          --controller "$controller" --uncertainty-case "$c" --uncertainty-on controller \
          --steps 20 --out "$work/walk" --no-plots --no-poincare --quiet >/dev/null
        /usr/bin/python3 scripts/walk_row.py "$work/walk/summary.json" "$gait" "$robot" \
          "$controller" "$c" >>"$out/mu_cases.csv"
      done
    done
  done
done
/usr/bin/python3 - "$out/mu_cases.csv" >"$out/mu_cases.md" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
print("| gait | robot | controller | case 1 | case 2 | case 3 |")
print("|---|---|---|---|---|---|")
key = lambda r: (r["gait"], r["robot"], r["controller"])
for k in dict.fromkeys(key(r) for r in rows):
    cells = []
    for r in (r for r in rows if key(r) == k):
        cells.append(f"{r['steps']} of 20" + ("" if r["steps"] == "20" else f" ({r['failure']})"))
    print(f"| {k[0]} | {k[1]} | {k[2]} | " + " | ".join(cells) + " |")
PY
cat "$out/mu_cases.md"
